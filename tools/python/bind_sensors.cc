// airis.Sensor: a non-image sensor's latest sample and its samples since the last read, as
// structured NumPy arrays with the columns of the dataset's streams.
#include <pybind11/stl.h>

#include "tools/python/bindings.h"
#include "tools/python/handles.h"

namespace airis::python {
namespace {

SampleBuffer& Buffer(const SensorHandle& h) {
  SampleBuffer* b = h.sim->samples(h.vehicle, h.sensor);
  if (!b) {
    throw py::type_error("sensor '" + h.get().name() + "' is a camera: use vehicle.cameras");
  }
  return *b;
}

}  // namespace

void BindSensors(py::module_& m) {
  py::class_<SensorHandle>(m, "Sensor",
                           "A sensor of a vehicle (IMU, barometer, magnetometer, GPS, rangefinder, "
                           "lidar). Rows hold time_ns then the columns of <vehicle>.<sensor> in a "
                           "dataset, with the same types (docs/dataset-format.md)")
      .def_property_readonly("name", [](const SensorHandle& h) { return h.get().name(); })
      .def_property_readonly("is_camera",
                             [](const SensorHandle& h) { return h.get().image() != nullptr; })
      .def_property_readonly("rate_hz",
                             [](const SensorHandle& h) { return h.get().schedule().rate_hz(); })
      .def_property_readonly("columns",
                             [](const SensorHandle& h) {
                               std::vector<std::string> out{"time_ns"};
                               for (const auto& c : h.get().columns()) out.push_back(c);
                               return out;
                             })
      .def_property_readonly("dtype",
                             [](const SensorHandle& h) { return DtypeOf(Buffer(h).layout()); })
      .def(
          "latest",
          [](const SensorHandle& h) -> py::object {
            const engine::Sensor& s = h.get();
            if (s.last_sample_ns() < 0) return py::none();
            const SampleBuffer& b = Buffer(h);
            return RecordsArray(b.PackLatest(s), DtypeOf(b.layout()))[py::int_(0)];
          },
          "The last sample as one record (numpy.void; fields by column name), None before the "
          "first")
      .def(
          "since_last",
          [](const SensorHandle& h) {
            SampleBuffer& b = Buffer(h);
            return RecordsArray(b.Take(), DtypeOf(b.layout()));
          },
          "Every sample since the previous call (or the start), one row each, as a structured "
          "array that owns its memory (no copy)")
      .def_property_readonly("pending", [](const SensorHandle& h) { return Buffer(h).rows(); })
      .def_property_readonly(
          "dropped", [](const SensorHandle& h) { return Buffer(h).dropped(); },
          "samples lost because more than max_samples were left unread")
      .def("__repr__", [](const SensorHandle& h) {
        return "<airis.Sensor '" + h.get().name() + "' of '" +
               h.sim->world().vehicle(h.vehicle).name() + "'>";
      });
}

}  // namespace airis::python
