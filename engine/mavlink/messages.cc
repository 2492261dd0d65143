#include "engine/mavlink/messages.h"

#include <array>

#include "engine/mavlink/payload.h"

namespace airis::engine::mavlink {
namespace {

// Each table entry's payload lengths must be what its field list adds up to, and ids must increase:
// both are checked here, at compile time, so a mistyped field or length does not build.
template <Message M>
constexpr bool LengthsMatchFields() {
  constexpr auto lengths = CalcWireLengths<M>();
  return lengths[0] == M::kInfo.base_length && lengths[1] == M::kInfo.full_length;
}

constexpr auto MakeTable() {
  std::array<MessageInfo, KnownMessageTypes::kCount> table{};
  std::size_t i = 0;
  KnownMessageTypes::ForEach([&](auto m) { table[i++] = decltype(m)::kInfo; });
  return table;
}

constexpr auto kTable = MakeTable();

constexpr bool IdsIncrease() {
  for (std::size_t i = 1; i < kTable.size(); ++i) {
    if (kTable[i].id <= kTable[i - 1].id) return false;
  }
  return true;
}

constexpr bool AllLengthsMatch() {
  bool ok = true;
  KnownMessageTypes::ForEach([&](auto m) { ok = ok && LengthsMatchFields<decltype(m)>(); });
  return ok;
}

static_assert(IdsIncrease(), "KnownMessageTypes must be listed in increasing id order");
static_assert(AllLengthsMatch(), "a kInfo payload length disagrees with its Fields list");

// Every known id is below 256, so a direct index answers FindMessageInfo in one load (the parser
// asks it once per frame). kNone marks ids that are not known.
constexpr std::uint8_t kNone = 0xFF;
static_assert(kTable.size() < kNone);

constexpr std::array<std::uint8_t, 256> MakeIndex() {
  std::array<std::uint8_t, 256> index{};
  index.fill(kNone);
  for (std::size_t i = 0; i < kTable.size(); ++i) {
    index[kTable[i].id] = static_cast<std::uint8_t>(i);
  }
  return index;
}

constexpr bool AllIdsBelow256() {
  for (const auto& info : kTable) {
    if (info.id >= 256) return false;
  }
  return true;
}
static_assert(AllIdsBelow256(), "FindMessageInfo's direct index assumes ids < 256");

constexpr auto kIndex = MakeIndex();

}  // namespace

const MessageInfo* FindMessageInfo(std::uint32_t id) {
  if (id >= kIndex.size() || kIndex[id] == kNone) return nullptr;
  return &kTable[kIndex[id]];
}

std::span<const MessageInfo> KnownMessages() { return kTable; }

}  // namespace airis::engine::mavlink
