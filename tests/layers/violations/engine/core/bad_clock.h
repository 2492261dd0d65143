#pragma once
// A deliberate violation for tests/layers: the engine includes a concrete sensor.
#include "engine/core/clock.h"
#include "sensors/imu.h"
