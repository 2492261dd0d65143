#include "scenes/mission_step_kinds.h"

namespace airis::scenes {

std::span<const MissionStepKind> MissionStepKinds() {
  static const MissionStepKind kKinds[] = {
      MissionStepKindOf<engine::TakeoffStep>(),     MissionStepKindOf<engine::GotoStep>(),
      MissionStepKindOf<engine::PathStep>(),        MissionStepKindOf<engine::OrbitStep>(),
      MissionStepKindOf<engine::HoverStep>(),       MissionStepKindOf<engine::YawStep>(),
      MissionStepKindOf<engine::LandStep>(),        MissionStepKindOf<engine::SurveyStep>(),
      MissionStepKindOf<engine::WaitStep>(),        MissionStepKindOf<engine::CaptureStep>(),
      MissionStepKindOf<engine::RandomPosesStep>(), MissionStepKindOf<engine::SetWindStep>(),
      MissionStepKindOf<engine::BarrierStep>(),
  };
  return kKinds;
}

}  // namespace airis::scenes
