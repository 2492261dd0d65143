#pragma once
// Allowed includes, which the check must accept.
#include "engine/physics/rigid_body.h"
#include <Eigen/Core>
