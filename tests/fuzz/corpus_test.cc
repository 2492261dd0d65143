// The generated MAVLink seeds (tests/fuzz/make_corpus.py, which frames them with its own CRC code)
// are what their names say, read by airis's parser: a valid frame of the named message, or a broken
// frame that yields nothing. The mesh seeds are checked in tests/scenes/mesh_file_check_test.cc.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "engine/mavlink/frame_parser.h"
#include "engine/mavlink/message_info.h"

namespace airis::engine::mavlink {
namespace {

namespace fs = std::filesystem;

// The tests run in the source folder (tests/fuzz/CMakeLists.txt).
const fs::path kSeeds = fs::path("tests") / "fuzz" / "corpus" / "mavlink";

/// Names of the messages in the frames the parser yields for a seed (its first byte, the target's
/// chunking choice, left out).
std::vector<std::string> FramesOf(const fs::path& seed) {
  std::ifstream in(seed, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  std::vector<std::string> names;
  if (bytes.empty()) return names;
  std::span<const std::uint8_t> input(bytes.data() + 1, bytes.size() - 1);
  FrameParser parser;
  while (const Frame* frame = parser.Next(input)) names.push_back(frame->info->name);
  return names;
}

TEST(FuzzCorpusTest, MavlinkSeedsAreWhatTheirNamesSay) {
  std::size_t valid = 0;
  std::size_t broken = 0;
  for (const MessageInfo& info : KnownMessages()) {
    const std::string stem = std::string("gen_") + info.name;
    for (const char* kind : {"_v2", "_v2_truncated", "_v2_signed", "_v1", "_v2_chunked"}) {
      const fs::path seed = kSeeds / (stem + kind);
      if (!fs::exists(seed)) {
        EXPECT_EQ(std::string(kind), "_v1") << seed << " missing (only v1 may be, for ids > 255)";
        continue;
      }
      EXPECT_EQ(FramesOf(seed), std::vector<std::string>{info.name}) << seed;
      ++valid;
    }
    for (const char* kind : {"_bad_crc", "_cut", "_bad_flags"}) {
      EXPECT_TRUE(FramesOf(kSeeds / (stem + kind)).empty()) << stem + kind;
      ++broken;
    }
  }
  EXPECT_GE(valid, 4 * KnownMessages().size());
  EXPECT_EQ(broken, 3 * KnownMessages().size());
  EXPECT_EQ(FramesOf(kSeeds / "gen_every_message").size(), KnownMessages().size());
  EXPECT_TRUE(FramesOf(kSeeds / "gen_unknown_id").empty());
}

}  // namespace
}  // namespace airis::engine::mavlink
