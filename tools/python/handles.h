#pragma once

#include <cstddef>
#include <memory>

#include "tools/python/python_simulation.h"

namespace airis::python {

/// What the Python objects of one Simulation hold: the simulation (shared, so a Vehicle, Sensor
/// or Camera kept after the Simulation object is gone stays valid) and indices into its world.
struct VehicleHandle {
  std::shared_ptr<PythonSimulation> sim;
  std::size_t vehicle = 0;

  engine::Vehicle& get() const { return sim->world().vehicle(vehicle); }
};

struct SensorHandle {
  std::shared_ptr<PythonSimulation> sim;
  std::size_t vehicle = 0;
  std::size_t sensor = 0;

  engine::Sensor& get() const { return *sim->world().sensors(vehicle)[sensor]; }
};

}  // namespace airis::python
