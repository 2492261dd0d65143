#include "engine/mavlink/messages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <type_traits>

#include "engine/mavlink/crc.h"
#include "engine/mavlink/payload.h"
#include "tests/mavlink/test_messages.h"

namespace airis::engine::mavlink {
namespace {

struct Published {
  std::uint32_t id;
  const char* name;
  int crc_extra;
  int base_length;
  int full_length;
};

// The published definitions: ids and CRC_EXTRA as mavlink's generators derive them from common.xml
// (the first six also as shared/reference/parameters.md and px4-sitl-protocol.md list them),
// payload lengths from the field types of common.xml.
constexpr Published kPublished[] = {
    {0, "HEARTBEAT", 50, 9, 9},
    {1, "SYS_STATUS", 124, 31, 43},
    {2, "SYSTEM_TIME", 137, 12, 12},
    {22, "PARAM_VALUE", 220, 25, 25},
    {23, "PARAM_SET", 168, 23, 23},
    {24, "GPS_RAW_INT", 24, 30, 52},
    {30, "ATTITUDE", 39, 28, 28},
    {32, "LOCAL_POSITION_NED", 185, 28, 28},
    {33, "GLOBAL_POSITION_INT", 104, 28, 28},
    {65, "RC_CHANNELS", 118, 42, 42},
    {75, "COMMAND_INT", 158, 35, 35},
    {76, "COMMAND_LONG", 152, 33, 33},
    {77, "COMMAND_ACK", 143, 3, 10},
    {84, "SET_POSITION_TARGET_LOCAL_NED", 143, 53, 53},
    {85, "POSITION_TARGET_LOCAL_NED", 140, 51, 51},
    {86, "SET_POSITION_TARGET_GLOBAL_INT", 5, 53, 53},
    {93, "HIL_ACTUATOR_CONTROLS", 47, 81, 81},
    {107, "HIL_SENSOR", 108, 64, 65},
    {113, "HIL_GPS", 124, 36, 39},
    {115, "HIL_STATE_QUATERNION", 4, 64, 64},
    {132, "DISTANCE_SENSOR", 85, 14, 39},
    {242, "HOME_POSITION", 104, 52, 60},
    {245, "EXTENDED_SYS_STATE", 130, 2, 2},
    {253, "STATUSTEXT", 83, 51, 54},
};

TEST(MessagesTest, TableEqualsThePublishedDefinitions) {
  const auto table = KnownMessages();
  ASSERT_EQ(table.size(), std::size(kPublished));
  for (std::size_t i = 0; i < table.size(); ++i) {
    SCOPED_TRACE(kPublished[i].name);
    EXPECT_EQ(table[i].id, kPublished[i].id);
    EXPECT_STREQ(table[i].name, kPublished[i].name);
    EXPECT_EQ(table[i].crc_extra, kPublished[i].crc_extra);
    EXPECT_EQ(table[i].base_length, kPublished[i].base_length);
    EXPECT_EQ(table[i].full_length, kPublished[i].full_length);
  }
}

TEST(MessagesTest, FindMessageInfoKnowsTheTableAndNothingElse) {
  for (const auto& p : kPublished) {
    const MessageInfo* info = FindMessageInfo(p.id);
    ASSERT_NE(info, nullptr) << p.name;
    EXPECT_STREQ(info->name, p.name);
  }
  EXPECT_EQ(FindMessageInfo(31), nullptr);  // ATTITUDE_QUATERNION: a real message, not ours
  EXPECT_EQ(FindMessageInfo(255), nullptr);
  EXPECT_EQ(FindMessageInfo(256 + 107), nullptr);  // 24-bit ids are not folded onto 8 bits
  EXPECT_EQ(FindMessageInfo(0xFFFFFF), nullptr);
}

// The name of a field's type as common.xml spells it (for arrays, of the element).
template <class T>
const char* XmlTypeName() {
  if constexpr (std::is_same_v<T, char>) return "char";
  if constexpr (std::is_same_v<T, std::uint8_t>) return "uint8_t";
  if constexpr (std::is_same_v<T, std::int8_t>) return "int8_t";
  if constexpr (std::is_same_v<T, std::uint16_t>) return "uint16_t";
  if constexpr (std::is_same_v<T, std::int16_t>) return "int16_t";
  if constexpr (std::is_same_v<T, std::uint32_t>) return "uint32_t";
  if constexpr (std::is_same_v<T, std::int32_t>) return "int32_t";
  if constexpr (std::is_same_v<T, std::uint64_t>) return "uint64_t";
  if constexpr (std::is_same_v<T, std::int64_t>) return "int64_t";
  if constexpr (std::is_same_v<T, float>) return "float";
  if constexpr (std::is_same_v<T, double>) return "double";
}

// CRC_EXTRA recomputed from a field list: CRC over "NAME ", then for each base field in wire order
// "type name " and, for an array, its length byte; folded to one byte (low XOR high).
class CrcExtraOfFields {
 public:
  explicit CrcExtraOfFields(const char* message_name) { Add(std::string(message_name) + " "); }
  template <class T>
  void operator()(const char* name, const T& /*value*/) {
    if (in_extensions_) return;
    if constexpr (testing::IsStdArray<T>::value) {
      Add(std::string(XmlTypeName<typename T::value_type>()) + " " + name + " ");
      crc_ = CrcAccumulate(static_cast<std::uint8_t>(std::tuple_size_v<T>), crc_);
    } else {
      Add(std::string(XmlTypeName<T>()) + " " + name + " ");
    }
  }
  void Extensions() { in_extensions_ = true; }
  std::uint8_t value() const { return static_cast<std::uint8_t>((crc_ & 0xFF) ^ (crc_ >> 8)); }

 private:
  void Add(const std::string& s) {
    for (char c : s) crc_ = CrcAccumulate(static_cast<std::uint8_t>(c), crc_);
  }
  std::uint16_t crc_ = kCrcInit;
  bool in_extensions_ = false;
};

// CRC_EXTRA depends on the field names, types and wire order, so this checks each struct's field
// list against common.xml's definition as its published CRC_EXTRA encodes it: a misspelt, retyped
// or misplaced base field fails here (extension fields are covered by the lengths and the
// conformance test).
TEST(MessagesTest, CrcExtraOfEachFieldListEqualsTheTable) {
  KnownMessageTypes::ForEach([](auto m) {
    using M = decltype(m);
    CrcExtraOfFields crc(M::kInfo.name);
    M::Fields(m, crc);
    EXPECT_EQ(crc.value(), M::kInfo.crc_extra) << M::kInfo.name;
  });
}

TEST(MessagesTest, VisitMessageTypeFindsEachIdAndRejectsOthers) {
  for (const auto& p : kPublished) {
    std::string found;
    EXPECT_TRUE(VisitMessageType(p.id, [&](auto m) { found = decltype(m)::kInfo.name; }));
    EXPECT_EQ(found, p.name);
  }
  EXPECT_FALSE(VisitMessageType(31, [](auto) { FAIL() << "called for an unknown id"; }));
}

TEST(MessagesTest, SetTextTruncatesAndZeroPads) {
  ParamSet p;
  SetText(p.param_id, "MPC_XY_VEL_MAX");
  EXPECT_EQ(GetText(p.param_id), "MPC_XY_VEL_MAX");
  EXPECT_EQ(p.param_id[14], '\0');
  SetText(p.param_id, "A_NAME_OF_EXACTLY_16");  // 20 characters: only 16 fit, with no NUL
  EXPECT_EQ(GetText(p.param_id), "A_NAME_OF_EXACTL");
  SetText(p.param_id, "");
  EXPECT_EQ(GetText(p.param_id), "");
}

TEST(MessagesTest, HeartbeatDefaultsToMavlinkVersion3) {
  EXPECT_EQ(Heartbeat{}.mavlink_version, 3);
}

}  // namespace
}  // namespace airis::engine::mavlink
