// The key reference of doc/scenes.md is what the scene reader reads by: `cosmems keys` prints
// SceneKeyReference(), and the document holds it verbatim between its markers, so a key added,
// renamed or given another default or bound without the document following fails here.
#include "cosmems/scene/scene_key_reference.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cosmems/scene/scene_loader.hpp"

namespace cosmems {
namespace {

std::string DocumentedReference() {
  std::ifstream file(COSMEMS_DOC_DIR "/scenes.md");
  std::stringstream text;
  text << file.rdbuf();
  const std::string doc = text.str();
  const std::string begin = "<!-- keys: cosmems keys -->\n", end = "<!-- /keys -->";
  const std::size_t from = doc.find(begin), to = doc.find(end);
  if (from == std::string::npos || to == std::string::npos || to < from) return "";
  return doc.substr(from + begin.size(), to - from - begin.size());
}

TEST(SceneKeyReferenceTest, DocumentHoldsTheReferenceTheReaderReadsBy) {
  EXPECT_EQ(DocumentedReference(), SceneKeyReference())
      << "regenerate doc/scenes.md's key reference with `cosmems keys`";
}

// Every key the reference names is one the reader knows: set alone on a scene that does not use
// it, it is no unknown key (the reference and RejectUnknownKeys come from the same visits).
TEST(SceneKeyReferenceTest, EveryDocumentedKeyIsKnownToTheReader) {
  std::istringstream rows(SceneKeyReference());
  std::string row;
  int keys = 0;
  while (std::getline(rows, row)) {
    if (row.rfind("| `", 0) != 0) continue;
    const std::string key = row.substr(3, row.find('`', 3) - 3);
    ++keys;
    try {
      LoadScene("cantilever", {SceneOverride{key, "0"}});
    } catch (const SceneError& error) {
      EXPECT_EQ(std::string(error.what()).find("unknown"), std::string::npos)
          << key << ": " << error.what();
    }
  }
  EXPECT_GT(keys, 50);
}

}  // namespace
}  // namespace cosmems
