#pragma once

// Named values of the MAVLink enums that the messages of this codec carry and the PX4 bridge needs,
// with their meaning as mavlink's common.xml (and minimal.xml, which it includes) states it. Each
// name is the common.xml entry name in our spelling: MAV_CMD_NAV_TAKEOFF is kMavCmdNavTakeoff. The
// message fields stay plain integers (a receiver must accept values this list does not name), so
// these are typed like the fields they go into.

#include <cstdint>

namespace airis::engine::mavlink {

// MAV_CMD (COMMAND_LONG.command, COMMAND_INT.command, COMMAND_ACK.command).
/// MAV_CMD_NAV_LAND: land at a location. param1 abort altitude [m], param2 precision land mode,
/// param4 yaw [deg] (NaN: current heading mode), param5/6 latitude/longitude, param7 altitude [m].
inline constexpr std::uint16_t kMavCmdNavLand = 21;
/// MAV_CMD_NAV_TAKEOFF: take off from ground / hand. param1 minimum pitch [deg], param4 yaw [deg]
/// (NaN: current heading mode), param5/6 latitude/longitude, param7 altitude [m].
inline constexpr std::uint16_t kMavCmdNavTakeoff = 22;
/// MAV_CMD_DO_SET_MODE: set the system mode. param1 MAV_MODE_FLAG bits, param2 custom mode, param3
/// custom sub mode (used when param1 has MAV_MODE_FLAG_CUSTOM_MODE_ENABLED).
inline constexpr std::uint16_t kMavCmdDoSetMode = 176;
/// MAV_CMD_DO_REPOSITION: fly to a WGS84 position (guided). param1 ground speed [m/s] (-1:
/// default), param2 MAV_DO_REPOSITION_FLAGS, param3 loiter radius [m], param4 yaw [rad] (NaN:
/// current heading mode), param5/6 latitude/longitude, param7 altitude [m].
inline constexpr std::uint16_t kMavCmdDoReposition = 192;
/// MAV_CMD_COMPONENT_ARM_DISARM: param1 1 arm, 0 disarm; param2 21196 forces it past the checks.
inline constexpr std::uint16_t kMavCmdComponentArmDisarm = 400;
/// MAV_CMD_SET_MESSAGE_INTERVAL: param1 message id, param2 interval [us] (-1: off, 0: default).
inline constexpr std::uint16_t kMavCmdSetMessageInterval = 511;
/// MAV_CMD_REQUEST_MESSAGE: emit one instance of message param1.
inline constexpr std::uint16_t kMavCmdRequestMessage = 512;
/// The param2 of MAV_CMD_COMPONENT_ARM_DISARM that forces arming or disarming.
inline constexpr float kArmDisarmForceMagic = 21196.0f;

// MAV_RESULT (COMMAND_ACK.result).
/// MAV_RESULT_ACCEPTED: the command is valid (supported, valid parameters) and was executed.
inline constexpr std::uint8_t kMavResultAccepted = 0;
/// MAV_RESULT_TEMPORARILY_REJECTED: valid, but cannot be executed now; retrying later may work.
inline constexpr std::uint8_t kMavResultTemporarilyRejected = 1;
/// MAV_RESULT_DENIED: supported, but a parameter value is invalid.
inline constexpr std::uint8_t kMavResultDenied = 2;
/// MAV_RESULT_UNSUPPORTED: the command is not supported (unknown).
inline constexpr std::uint8_t kMavResultUnsupported = 3;
/// MAV_RESULT_FAILED: valid, but execution failed (a non-temporary problem).
inline constexpr std::uint8_t kMavResultFailed = 4;
/// MAV_RESULT_IN_PROGRESS: valid and being executed; COMMAND_ACK.progress tells how far.
inline constexpr std::uint8_t kMavResultInProgress = 5;
/// MAV_RESULT_CANCELLED: cancelled by a COMMAND_CANCEL.
inline constexpr std::uint8_t kMavResultCancelled = 6;
/// MAV_RESULT_COMMAND_LONG_ONLY: accepted only as a COMMAND_LONG.
inline constexpr std::uint8_t kMavResultCommandLongOnly = 7;
/// MAV_RESULT_COMMAND_INT_ONLY: accepted only as a COMMAND_INT.
inline constexpr std::uint8_t kMavResultCommandIntOnly = 8;
/// MAV_RESULT_COMMAND_UNSUPPORTED_MAV_FRAME: the command's frame is not supported.
inline constexpr std::uint8_t kMavResultCommandUnsupportedMavFrame = 9;
/// MAV_RESULT_NOT_IN_CONTROL: the sender is not in control of the target.
inline constexpr std::uint8_t kMavResultNotInControl = 10;

// MAV_MODE_FLAG (HEARTBEAT.base_mode, HIL_ACTUATOR_CONTROLS.mode): a bitmask.
/// MAV_MODE_FLAG_CUSTOM_MODE_ENABLED: a system-specific custom mode is enabled (in custom_mode).
inline constexpr std::uint8_t kMavModeFlagCustomModeEnabled = 1;
/// MAV_MODE_FLAG_TEST_ENABLED: a test mode is enabled (temporary system tests).
inline constexpr std::uint8_t kMavModeFlagTestEnabled = 2;
/// MAV_MODE_FLAG_AUTO_ENABLED: autonomous mode, the system finds its own goal positions.
inline constexpr std::uint8_t kMavModeFlagAutoEnabled = 4;
/// MAV_MODE_FLAG_GUIDED_ENABLED: guided mode, the system flies waypoints / mission items.
inline constexpr std::uint8_t kMavModeFlagGuidedEnabled = 8;
/// MAV_MODE_FLAG_STABILIZE_ENABLED: the system stabilises its attitude (and maybe position).
inline constexpr std::uint8_t kMavModeFlagStabilizeEnabled = 16;
/// MAV_MODE_FLAG_HIL_ENABLED: hardware in the loop; actuators blocked, software fully operational.
inline constexpr std::uint8_t kMavModeFlagHilEnabled = 32;
/// MAV_MODE_FLAG_MANUAL_INPUT_ENABLED: remote control input is enabled.
inline constexpr std::uint8_t kMavModeFlagManualInputEnabled = 64;
/// MAV_MODE_FLAG_SAFETY_ARMED: armed; motors are enabled / running / can start.
inline constexpr std::uint8_t kMavModeFlagSafetyArmed = 128;

// MAV_STATE (HEARTBEAT.system_status).
inline constexpr std::uint8_t kMavStateUninit = 0;  ///< MAV_STATE_UNINIT: state unknown
inline constexpr std::uint8_t kMavStateBoot = 1;    ///< MAV_STATE_BOOT: booting up
/// MAV_STATE_CALIBRATING: not flight-ready
inline constexpr std::uint8_t kMavStateCalibrating = 2;
/// MAV_STATE_STANDBY: grounded, can launch any time
inline constexpr std::uint8_t kMavStateStandby = 3;
/// MAV_STATE_ACTIVE: motors engaged, maybe airborne
inline constexpr std::uint8_t kMavStateActive = 4;
/// MAV_STATE_CRITICAL: failsafe, still navigates
inline constexpr std::uint8_t kMavStateCritical = 5;
/// MAV_STATE_EMERGENCY: lost control, mayday
inline constexpr std::uint8_t kMavStateEmergency = 6;
inline constexpr std::uint8_t kMavStatePoweroff = 7;  ///< MAV_STATE_POWEROFF: shutting down
/// MAV_STATE_FLIGHT_TERMINATION: terminating itself (failsafe or commanded).
inline constexpr std::uint8_t kMavStateFlightTermination = 8;

// MAV_TYPE (HEARTBEAT.type): the values a simulator, a ground station or PX4 puts there.
inline constexpr std::uint8_t kMavTypeGeneric = 0;  ///< MAV_TYPE_GENERIC: generic micro air vehicle
inline constexpr std::uint8_t kMavTypeFixedWing = 1;   ///< MAV_TYPE_FIXED_WING: fixed-wing aircraft
inline constexpr std::uint8_t kMavTypeQuadrotor = 2;   ///< MAV_TYPE_QUADROTOR: quadrotor
inline constexpr std::uint8_t kMavTypeHelicopter = 4;  ///< MAV_TYPE_HELICOPTER: with tail rotor
/// MAV_TYPE_GCS: ground control station / operator unit
inline constexpr std::uint8_t kMavTypeGcs = 6;
inline constexpr std::uint8_t kMavTypeHexarotor = 13;  ///< MAV_TYPE_HEXAROTOR: hexarotor
inline constexpr std::uint8_t kMavTypeOctorotor = 14;  ///< MAV_TYPE_OCTOROTOR: octorotor
inline constexpr std::uint8_t kMavTypeTricopter = 15;  ///< MAV_TYPE_TRICOPTER: tricopter
/// MAV_TYPE_ONBOARD_CONTROLLER: an onboard companion controller.
inline constexpr std::uint8_t kMavTypeOnboardController = 18;
/// MAV_TYPE_GENERIC_MULTIROTOR: a multirotor of no specific or of unknown type.
inline constexpr std::uint8_t kMavTypeGenericMultirotor = 43;

// MAV_AUTOPILOT (HEARTBEAT.autopilot).
/// MAV_AUTOPILOT_GENERIC: generic autopilot, full support for everything.
inline constexpr std::uint8_t kMavAutopilotGeneric = 0;
/// MAV_AUTOPILOT_ARDUPILOTMEGA: ArduPilot (Plane, Copter, Rover, Sub, Tracker).
inline constexpr std::uint8_t kMavAutopilotArdupilotmega = 3;
/// MAV_AUTOPILOT_INVALID: not a flight controller (a ground station, a simulator, another
/// component).
inline constexpr std::uint8_t kMavAutopilotInvalid = 8;
/// MAV_AUTOPILOT_PX4: the PX4 autopilot.
inline constexpr std::uint8_t kMavAutopilotPx4 = 12;

// MAV_FRAME (COMMAND_INT.frame, *_POSITION_TARGET_*.coordinate_frame).
/// MAV_FRAME_GLOBAL: WGS84 latitude/longitude, altitude above mean sea level.
inline constexpr std::uint8_t kMavFrameGlobal = 0;
/// MAV_FRAME_LOCAL_NED: local tangent frame, x north, y east, z down, origin fixed to the earth.
inline constexpr std::uint8_t kMavFrameLocalNed = 1;
/// MAV_FRAME_MISSION: not a coordinate frame; marks a mission command.
inline constexpr std::uint8_t kMavFrameMission = 2;
/// MAV_FRAME_GLOBAL_RELATIVE_ALT: WGS84, altitude relative to the home position.
inline constexpr std::uint8_t kMavFrameGlobalRelativeAlt = 3;
/// MAV_FRAME_LOCAL_ENU: local tangent frame, x east, y north, z up, origin fixed to the earth.
inline constexpr std::uint8_t kMavFrameLocalEnu = 4;
/// MAV_FRAME_LOCAL_OFFSET_NED: NED axes, origin travelling with the vehicle.
inline constexpr std::uint8_t kMavFrameLocalOffsetNed = 7;
/// MAV_FRAME_BODY_NED: as LOCAL_NED for positions, as BODY_FRD for velocities and accelerations.
inline constexpr std::uint8_t kMavFrameBodyNed = 8;
/// MAV_FRAME_BODY_OFFSET_NED: the same as MAV_FRAME_BODY_FRD.
inline constexpr std::uint8_t kMavFrameBodyOffsetNed = 9;
/// MAV_FRAME_GLOBAL_TERRAIN_ALT: WGS84, altitude above ground level.
inline constexpr std::uint8_t kMavFrameGlobalTerrainAlt = 10;
/// MAV_FRAME_BODY_FRD: x forward, y right, z down, aligned with and travelling with the vehicle.
inline constexpr std::uint8_t kMavFrameBodyFrd = 12;

// MAV_LANDED_STATE (EXTENDED_SYS_STATE.landed_state).
/// MAV_LANDED_STATE_UNDEFINED: unknown
inline constexpr std::uint8_t kMavLandedStateUndefined = 0;
inline constexpr std::uint8_t kMavLandedStateOnGround = 1;  ///< MAV_LANDED_STATE_ON_GROUND: landed
inline constexpr std::uint8_t kMavLandedStateInAir = 2;     ///< MAV_LANDED_STATE_IN_AIR: in the air
inline constexpr std::uint8_t kMavLandedStateTakeoff = 3;  ///< MAV_LANDED_STATE_TAKEOFF: taking off
inline constexpr std::uint8_t kMavLandedStateLanding = 4;  ///< MAV_LANDED_STATE_LANDING: landing

// MAV_VTOL_STATE (EXTENDED_SYS_STATE.vtol_state).
inline constexpr std::uint8_t kMavVtolStateUndefined = 0;  ///< MAV_VTOL_STATE_UNDEFINED: not a VTOL
/// MAV_VTOL_STATE_TRANSITION_TO_FW: transition from multicopter to fixed-wing.
inline constexpr std::uint8_t kMavVtolStateTransitionToFw = 1;
/// MAV_VTOL_STATE_TRANSITION_TO_MC: transition from fixed-wing to multicopter.
inline constexpr std::uint8_t kMavVtolStateTransitionToMc = 2;
inline constexpr std::uint8_t kMavVtolStateMc = 3;  ///< MAV_VTOL_STATE_MC: multicopter state
inline constexpr std::uint8_t kMavVtolStateFw = 4;  ///< MAV_VTOL_STATE_FW: fixed-wing state

// MAV_SEVERITY (STATUSTEXT.severity), as RFC 5424.
/// MAV_SEVERITY_EMERGENCY: system unusable
inline constexpr std::uint8_t kMavSeverityEmergency = 0;
/// MAV_SEVERITY_ALERT: act immediately; an error in non-critical systems.
inline constexpr std::uint8_t kMavSeverityAlert = 1;
/// MAV_SEVERITY_CRITICAL: act immediately; a failure in a primary system.
inline constexpr std::uint8_t kMavSeverityCritical = 2;
/// MAV_SEVERITY_ERROR: an error in secondary / redundant systems.
inline constexpr std::uint8_t kMavSeverityError = 3;
/// MAV_SEVERITY_WARNING: a possible future error if not resolved (e.g. low battery).
inline constexpr std::uint8_t kMavSeverityWarning = 4;
/// MAV_SEVERITY_NOTICE: an unusual event, not an error; worth investigating.
inline constexpr std::uint8_t kMavSeverityNotice = 5;
/// MAV_SEVERITY_INFO: normal operational messages; no action needed.
inline constexpr std::uint8_t kMavSeverityInfo = 6;
/// MAV_SEVERITY_DEBUG: useful for debugging; should not occur in normal operation.
inline constexpr std::uint8_t kMavSeverityDebug = 7;

// MAV_PARAM_TYPE (PARAM_VALUE.param_type, PARAM_SET.param_type).
inline constexpr std::uint8_t kMavParamTypeUint8 = 1;    ///< MAV_PARAM_TYPE_UINT8
inline constexpr std::uint8_t kMavParamTypeInt8 = 2;     ///< MAV_PARAM_TYPE_INT8
inline constexpr std::uint8_t kMavParamTypeUint16 = 3;   ///< MAV_PARAM_TYPE_UINT16
inline constexpr std::uint8_t kMavParamTypeInt16 = 4;    ///< MAV_PARAM_TYPE_INT16
inline constexpr std::uint8_t kMavParamTypeUint32 = 5;   ///< MAV_PARAM_TYPE_UINT32
inline constexpr std::uint8_t kMavParamTypeInt32 = 6;    ///< MAV_PARAM_TYPE_INT32
inline constexpr std::uint8_t kMavParamTypeUint64 = 7;   ///< MAV_PARAM_TYPE_UINT64
inline constexpr std::uint8_t kMavParamTypeInt64 = 8;    ///< MAV_PARAM_TYPE_INT64
inline constexpr std::uint8_t kMavParamTypeReal32 = 9;   ///< MAV_PARAM_TYPE_REAL32: 32-bit float
inline constexpr std::uint8_t kMavParamTypeReal64 = 10;  ///< MAV_PARAM_TYPE_REAL64: 64-bit float

// GPS_FIX_TYPE (GPS_RAW_INT.fix_type; HIL_GPS.fix_type uses the same numbers 0..3).
inline constexpr std::uint8_t kGpsFixTypeNoGps = 0;  ///< GPS_FIX_TYPE_NO_GPS: no GPS connected
/// GPS_FIX_TYPE_NO_FIX: connected, no position
inline constexpr std::uint8_t kGpsFixTypeNoFix = 1;
inline constexpr std::uint8_t kGpsFixType2dFix = 2;     ///< GPS_FIX_TYPE_2D_FIX: 2D position
inline constexpr std::uint8_t kGpsFixType3dFix = 3;     ///< GPS_FIX_TYPE_3D_FIX: 3D position
inline constexpr std::uint8_t kGpsFixTypeDgps = 4;      ///< GPS_FIX_TYPE_DGPS: DGPS/SBAS-aided 3D
inline constexpr std::uint8_t kGpsFixTypeRtkFloat = 5;  ///< GPS_FIX_TYPE_RTK_FLOAT: RTK float, 3D
inline constexpr std::uint8_t kGpsFixTypeRtkFixed = 6;  ///< GPS_FIX_TYPE_RTK_FIXED: RTK fixed, 3D
/// GPS_FIX_TYPE_STATIC: static (base stations)
inline constexpr std::uint8_t kGpsFixTypeStatic = 7;
inline constexpr std::uint8_t kGpsFixTypePpp = 8;  ///< GPS_FIX_TYPE_PPP: PPP, 3D

// MAV_DISTANCE_SENSOR (DISTANCE_SENSOR.type).
inline constexpr std::uint8_t kMavDistanceSensorLaser = 0;  ///< MAV_DISTANCE_SENSOR_LASER: laser
inline constexpr std::uint8_t kMavDistanceSensorUltrasound = 1;  ///< MAV_DISTANCE_SENSOR_ULTRASOUND
inline constexpr std::uint8_t kMavDistanceSensorInfrared = 2;    ///< MAV_DISTANCE_SENSOR_INFRARED
inline constexpr std::uint8_t kMavDistanceSensorRadar = 3;       ///< MAV_DISTANCE_SENSOR_RADAR
/// MAV_DISTANCE_SENSOR_UNKNOWN: broken or unknown type (e.g. analog units).
inline constexpr std::uint8_t kMavDistanceSensorUnknown = 4;

// HIL_SENSOR_UPDATED_FLAGS (HIL_SENSOR.fields_updated): one bit per field that changed. PX4 takes a
// group (accel, gyro, mag, baro) only when every bit of the group is set.
inline constexpr std::uint32_t kHilSensorUpdatedXacc = 0x1;            ///< xacc updated
inline constexpr std::uint32_t kHilSensorUpdatedYacc = 0x2;            ///< yacc updated
inline constexpr std::uint32_t kHilSensorUpdatedZacc = 0x4;            ///< zacc updated
inline constexpr std::uint32_t kHilSensorUpdatedXgyro = 0x8;           ///< xgyro updated
inline constexpr std::uint32_t kHilSensorUpdatedYgyro = 0x10;          ///< ygyro updated
inline constexpr std::uint32_t kHilSensorUpdatedZgyro = 0x20;          ///< zgyro updated
inline constexpr std::uint32_t kHilSensorUpdatedXmag = 0x40;           ///< xmag updated
inline constexpr std::uint32_t kHilSensorUpdatedYmag = 0x80;           ///< ymag updated
inline constexpr std::uint32_t kHilSensorUpdatedZmag = 0x100;          ///< zmag updated
inline constexpr std::uint32_t kHilSensorUpdatedAbsPressure = 0x200;   ///< abs_pressure updated
inline constexpr std::uint32_t kHilSensorUpdatedDiffPressure = 0x400;  ///< diff_pressure updated
inline constexpr std::uint32_t kHilSensorUpdatedPressureAlt = 0x800;   ///< pressure_alt updated
inline constexpr std::uint32_t kHilSensorUpdatedTemperature = 0x1000;  ///< temperature updated
/// HIL_SENSOR_UPDATED_RESET: a full reset of attitude, position, velocities... was done in the sim.
inline constexpr std::uint32_t kHilSensorUpdatedReset = 0x80000000u;

// HIL_ACTUATOR_CONTROLS_FLAGS (HIL_ACTUATOR_CONTROLS.flags).
/// HIL_ACTUATOR_CONTROLS_FLAGS_LOCKSTEP: the simulation is using lockstep (value 1, i.e. bit 0).
inline constexpr std::uint64_t kHilActuatorControlsFlagsLockstep = 1;

// POSITION_TARGET_TYPEMASK (*_POSITION_TARGET_*.type_mask): a bit set means "ignore this
// dimension".
inline constexpr std::uint16_t kPositionTargetTypemaskXIgnore = 1;     ///< ignore position x
inline constexpr std::uint16_t kPositionTargetTypemaskYIgnore = 2;     ///< ignore position y
inline constexpr std::uint16_t kPositionTargetTypemaskZIgnore = 4;     ///< ignore position z
inline constexpr std::uint16_t kPositionTargetTypemaskVxIgnore = 8;    ///< ignore velocity x
inline constexpr std::uint16_t kPositionTargetTypemaskVyIgnore = 16;   ///< ignore velocity y
inline constexpr std::uint16_t kPositionTargetTypemaskVzIgnore = 32;   ///< ignore velocity z
inline constexpr std::uint16_t kPositionTargetTypemaskAxIgnore = 64;   ///< ignore acceleration x
inline constexpr std::uint16_t kPositionTargetTypemaskAyIgnore = 128;  ///< ignore acceleration y
inline constexpr std::uint16_t kPositionTargetTypemaskAzIgnore = 256;  ///< ignore acceleration z
/// POSITION_TARGET_TYPEMASK_FORCE_SET: afx/afy/afz are a force, not an acceleration.
inline constexpr std::uint16_t kPositionTargetTypemaskForceSet = 512;
inline constexpr std::uint16_t kPositionTargetTypemaskYawIgnore = 1024;      ///< ignore yaw
inline constexpr std::uint16_t kPositionTargetTypemaskYawRateIgnore = 2048;  ///< ignore yaw rate

}  // namespace airis::engine::mavlink
