#pragma once
// Allowed includes, which the check must accept.
#include <Eigen/Core>

#include "engine/physics/rigid_body.h"
