#include "sweep_store.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <system_error>

#include "atomic_file.hpp"
#include "cli_errors.hpp"
#include "csv_file.hpp"
#include "sweep_outputs.hpp"

namespace cosmems::internal {
namespace {

constexpr const char* kSweepFile = "sweep.json";
constexpr const char* kSamplesFile = "samples.jsonl";
// Values longer than this are named, not quoted, in the message of a differing sweep.
constexpr std::size_t kQuotedValueChars = 80;

// A cell of the CSV: a number exact, a string as it is unless it needs quotes.
std::string Cell(const nlohmann::ordered_json& value) {
  if (value.is_number()) return CsvFile::Number(value.get<double>());
  const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

[[noreturn]] void FailOnFile(const std::filesystem::path& path, const std::string& what,
                             int error) {
  throw OutputFileError(path.string() + ": " + what + ": " +
                        std::generic_category().message(error));
}

// samples.jsonl held exclusively: by every process that reads the folder or appends a row.
class SamplesLock {
 public:
  SamplesLock(int fd, const std::filesystem::path& path) : fd_(fd) {
    while (flock(fd_, LOCK_EX) != 0) {
      if (errno != EINTR) FailOnFile(path, "cannot lock", errno);
    }
  }
  ~SamplesLock() { flock(fd_, LOCK_UN); }
  SamplesLock(const SamplesLock&) = delete;
  SamplesLock& operator=(const SamplesLock&) = delete;

 private:
  int fd_;
};

// Under the lock, a last line without its newline was cut short by a process that died while
// writing it: it is dropped (its sample runs again), so that the next row starts a line.
// Returns the file's size after.
off_t DropTornLine(int fd, const std::filesystem::path& path) {
  struct stat status {};
  if (fstat(fd, &status) != 0) FailOnFile(path, "cannot read", errno);
  off_t end = status.st_size;
  char block[4096];
  while (end > 0) {
    const off_t start = end > static_cast<off_t>(sizeof block) ? end - sizeof block : 0;
    const ssize_t got = pread(fd, block, static_cast<std::size_t>(end - start), start);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) FailOnFile(path, "cannot read", got < 0 ? errno : EIO);
    ssize_t i = got;
    while (i > 0 && block[i - 1] != '\n') --i;
    if (i > 0) {
      end = start + i;
      break;
    }
    end = start;
  }
  if (end < status.st_size && ftruncate(fd, end) != 0) FailOnFile(path, "cannot write", errno);
  return end;
}

std::string ReadSamples(int fd, off_t size, const std::filesystem::path& path) {
  std::string text(static_cast<std::size_t>(size), '\0');
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t got = pread(fd, text.data() + done, text.size() - done, static_cast<off_t>(done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) FailOnFile(path, "cannot read", got < 0 ? errno : EIO);
    done += static_cast<std::size_t>(got);
  }
  return text;
}

// The keys of sweep.json whose values differ, each with both values when they are short.
std::string Differences(const nlohmann::ordered_json& before, const nlohmann::ordered_json& now) {
  if (!before.is_object()) return std::string(kSweepFile) + " is not a sweep's description";
  std::set<std::string> keys;
  for (const auto& [key, value] : before.items()) keys.insert(key);
  for (const auto& [key, value] : now.items()) keys.insert(key);
  std::string differences;
  for (const std::string& key : keys) {
    const bool there = before.contains(key), here = now.contains(key);
    if (there && here && before[key] == now[key]) continue;
    std::string difference = key;
    if (key == "scene_text_hash") difference += " (the scene's text)";
    const std::string old_value = there ? before[key].dump() : "absent";
    const std::string new_value = here ? now[key].dump() : "absent";
    if (old_value.size() + new_value.size() <= kQuotedValueChars) {
      difference += ": " + old_value + " there, " + new_value + " now";
    }
    differences += (differences.empty() ? "" : "; ") + difference;
  }
  return differences;
}

// Refuses a folder whose sweep.json describes another sweep, before anything is written.
void CheckSameSweep(const std::filesystem::path& asked, const nlohmann::ordered_json& sweep,
                    const std::string& where) {
  std::ifstream in(asked);
  if (!in) FailOnFile(asked, "cannot read", errno);
  const nlohmann::ordered_json before = nlohmann::ordered_json::parse(in, nullptr, false);
  if (before != sweep) {
    throw CliInputError(where + " holds another sweep (its " + kSweepFile + " differs in " +
                        Differences(before, sweep) + "): choose another folder or delete it");
  }
}

}  // namespace

SweepStore::SweepStore(const std::filesystem::path& directory,
                       const nlohmann::ordered_json& description, std::ostream& warnings)
    : directory_(directory), samples_path_(directory / kSamplesFile) {
  // As sweep.json will hold it: a scene file's name that is not UTF-8 with U+FFFD in place of
  // its stray bytes, so that the resume compares like with like.
  const nlohmann::ordered_json sweep = nlohmann::ordered_json::parse(
      description.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  const std::string where = "--out " + directory.string();
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory)) {
    throw CliInputError(where + ": cannot create the directory" +
                        (error ? ": " + error.message() : std::string()));
  }
  const std::filesystem::path asked = directory / kSweepFile;
  if (std::filesystem::exists(asked)) CheckSameSweep(asked, sweep, where);
  // Appending only; never through a symbolic link, which could point anywhere.
  samples_ =
      open(samples_path_.c_str(), O_RDWR | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (samples_ < 0) {
    FailOnFile(samples_path_, errno == ELOOP ? "a symbolic link, not followed" : "cannot open",
               errno);
  }
  const SamplesLock lock(samples_, samples_path_);
  // Another shard may have begun the folder since it was looked at.
  if (std::filesystem::exists(asked)) {
    CheckSameSweep(asked, sweep, where);
  } else {
    AtomicFile::WriteWhole(asked, sweep.dump(2) + "\n");
  }
  const std::string text =
      ReadSamples(samples_, DropTornLine(samples_, samples_path_), samples_path_);
  std::set<std::int64_t> seen;
  int line = 0;
  for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos;
       start = end + 1) {
    ++line;
    try {
      SweepRow row =
          SweepRow::FromJson(nlohmann::ordered_json::parse(text.substr(start, end - start)));
      if (seen.insert(row.index).second) previous_.push_back(std::move(row));
    } catch (const nlohmann::json::exception& e) {
      warnings << "cosmems: warning: " << samples_path_.string() << " line " << line
               << " is not a sample row (" << e.what() << "): skipped, its sample runs again\n";
    }
  }
}

SweepStore::~SweepStore() {
  if (samples_ >= 0) close(samples_);
}

void SweepStore::Append(const SweepRow& row) {
  const std::string line = row.Text() + "\n";
  const SamplesLock lock(samples_, samples_path_);
  (void)DropTornLine(samples_, samples_path_);
  // O_APPEND puts each write at the end; under the lock a short write is continued in place.
  for (std::size_t done = 0; done < line.size();) {
    const ssize_t wrote = write(samples_, line.data() + done, line.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote < 0) FailOnFile(samples_path_, "cannot write", errno);
    done += static_cast<std::size_t>(wrote);
  }
}

void WriteSweepCsv(const std::filesystem::path& path, const std::vector<SweepRow>& rows) {
  std::vector<std::string> keys, fields;
  std::set<std::string> known;
  for (const SweepRow& row : rows) {
    for (const auto& [key, value] : row.parameters.items()) {
      if (known.insert("parameter " + key).second) keys.push_back(key);
    }
    for (const auto& [field, value] : NumericOutputs(row.result)) {
      if (known.insert("output " + field).second) fields.push_back(field);
    }
  }
  std::string header = "index";
  for (const std::string& key : keys) header += "," + key;
  header += ",status";
  for (const std::string& field : fields) header += "," + field;
  CsvFile csv(path, header);
  for (const SweepRow& row : rows) {
    std::vector<std::string> cells = {std::to_string(row.index)};
    for (const std::string& key : keys) {
      cells.push_back(row.parameters.contains(key) ? Cell(row.parameters[key]) : "");
    }
    cells.push_back(Cell(row.status));
    std::map<std::string, double> outputs;
    for (const auto& [field, value] : NumericOutputs(row.result)) outputs[field] = value;
    for (const std::string& field : fields) {
      const auto found = outputs.find(field);
      cells.push_back(found == outputs.end() ? "" : CsvFile::Number(found->second));
    }
    csv.Row(cells);
  }
  csv.Close();
}

}  // namespace cosmems::internal
