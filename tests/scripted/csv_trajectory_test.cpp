#include "cosmems/scripted/csv_trajectory.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cosmems {
namespace {

/// Writes `content` to a file named after the running test, so parallel tests never share one.
std::string WriteFile(const std::string& content) {
  const std::string path = ::testing::TempDir() + "cosmems_scripted_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".csv";
  std::ofstream(path) << content;
  return path;
}

/// The message LoadCsvTrajectory() throws for `content`, which must mention the file, "path:line"
/// and each of `expected`.
void ExpectError(const std::string& content, int line, const std::vector<std::string>& expected) {
  const std::string path = WriteFile(content);
  try {
    LoadCsvTrajectory(path);
    ADD_FAILURE() << "no error for:\n" << content;
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path + ":" + std::to_string(line) + ":"), std::string::npos) << message;
    for (const std::string& part : expected) {
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' in: " << message;
    }
  }
}

TEST(CsvTrajectoryTest, InterpolatesLinearlyAndHoldsOutsideTheSamples) {
  const std::string path = WriteFile(
      "time_s,x_m,y_m,z_m\n"
      "0.5, 0.0, 0.01, 0.0\n"
      "1.5, 0.02, -0.01, 0.004\r\n"
      "\n"
      "2.5,0.02,0.03,0.004\n");
  const auto trajectory = LoadCsvTrajectory(path);
  EXPECT_EQ(trajectory->Duration(), 2.5);
  EXPECT_EQ(trajectory->Position(0.0), Eigen::Vector3d(0.0, 0.01, 0.0));
  EXPECT_EQ(trajectory->Position(0.5), Eigen::Vector3d(0.0, 0.01, 0.0));
  EXPECT_EQ(trajectory->Position(1.5), Eigen::Vector3d(0.02, -0.01, 0.004));
  EXPECT_EQ(trajectory->Position(9.0), Eigen::Vector3d(0.02, 0.03, 0.004));
  // Quarter of the way from 0.5 s to 1.5 s: a few roundings of centimetre values (ulp 1.7e-18 m).
  const Eigen::Vector3d quarter(0.005, 0.005, 0.001);
  EXPECT_LT((trajectory->Position(0.75) - quarter).norm(), 1e-16);
  const Eigen::Vector3d middle(0.02, 0.01, 0.004);
  EXPECT_LT((trajectory->Position(2.0) - middle).norm(), 1e-16);
}

TEST(CsvTrajectoryTest, IgnoresColumnsAfterTheFourth) {
  const auto trajectory =
      LoadCsvTrajectory(WriteFile("time_s,x_m,y_m,z_m,fx_n,note\n"
                                  "0,1,2,3,0.5,anything\n"
                                  "1,2,3,4,0.5,at all\n"));
  EXPECT_EQ(trajectory->Duration(), 1.0);
  EXPECT_EQ(trajectory->Position(1.0), Eigen::Vector3d(2, 3, 4));
}

TEST(CsvTrajectoryTest, MissingFileIsNamed) {
  const std::string path = ::testing::TempDir() + "cosmems_scripted_no_such_file.csv";
  try {
    LoadCsvTrajectory(path);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(path + ": cannot open"), std::string::npos)
        << error.what();
  }
}

// A FIFO, a device or a directory would be read for ever (or not at all): each is refused by
// name before a byte is read.
TEST(CsvTrajectoryTest, OnlyARegularFileIsRead) {
  const std::string fifo = ::testing::TempDir() + "cosmems_scripted_trajectory_fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, std::string("/dev/zero"), ::testing::TempDir()}) {
    try {
      LoadCsvTrajectory(path);
      ADD_FAILURE() << path << ": no error";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(path + ": not a regular file"), std::string::npos)
          << error.what();
    }
  }
  std::remove(fifo.c_str());
}

TEST(CsvTrajectoryTest, EmptyFileNeedsTheHeader) {
  ExpectError("", 1, {"header", "time_s,x_m,y_m,z_m"});
}

TEST(CsvTrajectoryTest, ShortHeaderIsRejected) {
  ExpectError("time_s,x_m,y_m\n0,0,0\n", 1, {"3 fields", "time_s,x_m,y_m,z_m"});
}

TEST(CsvTrajectoryTest, WrongHeaderColumnIsNamed) {
  ExpectError("time_s,x_mm,y_m,z_m\n0,0,0,0\n", 1, {"column 2", "'x_mm'", "'x_m'"});
}

TEST(CsvTrajectoryTest, MissingHeaderIsRejected) {
  ExpectError("0,0,0,0\n1,0,0,0\n", 1, {"column 1", "'0'", "'time_s'"});
}

TEST(CsvTrajectoryTest, WrongFieldCountGivesTheLine) {
  ExpectError("time_s,x_m,y_m,z_m\n0,0,0,0\n1,0,0\n", 3, {"3 fields", "expected 4"});
}

TEST(CsvTrajectoryTest, NonNumberIsNamed) {
  ExpectError("time_s,x_m,y_m,z_m\n0,0,0,0\n\n1,0,0.0.1,0\n", 4, {"y_m = '0.0.1'", "not a number"});
}

TEST(CsvTrajectoryTest, EmptyFieldIsNamed) {
  ExpectError("time_s,x_m,y_m,z_m\n0,,0,0\n", 2, {"x_m = ''", "not a number"});
}

TEST(CsvTrajectoryTest, NanIsRejected) {
  ExpectError("time_s,x_m,y_m,z_m\n0,0,0,nan\n", 2, {"z_m = 'nan'", "not finite"});
}

TEST(CsvTrajectoryTest, InfiniteTimeIsRejected) {
  ExpectError("time_s,x_m,y_m,z_m\ninf,0,0,0\n", 2, {"time_s = 'inf'", "not finite"});
}

TEST(CsvTrajectoryTest, DecreasingTimeIsRejected) {
  ExpectError("time_s,x_m,y_m,z_m\n0,0,0,0\n0.2,0,0,0\n0.1,0,0,0\n", 4,
              {"time_s = '0.1'", "0.2", "increase"});
}

TEST(CsvTrajectoryTest, RepeatedTimeIsRejected) {
  ExpectError("time_s,x_m,y_m,z_m\n0,0,0,0\n0,1,0,0\n", 3, {"time_s = '0'", "increase"});
}

TEST(CsvTrajectoryTest, HeaderAloneIsRejected) {
  const std::string path = WriteFile("time_s,x_m,y_m,z_m\n");
  try {
    LoadCsvTrajectory(path);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(path + ": no data rows"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace cosmems
