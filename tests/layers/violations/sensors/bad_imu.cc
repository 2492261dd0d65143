// Deliberate violations for tests/layers: a sensor includes a vehicle and the scene loader's YAML.
#include <yaml-cpp/yaml.h>

#include "vehicles/multirotor/multirotor.h"
