// The extension module airis._airis: exceptions, then the parts in bind_*.cc. The pure-Python
// package airis (tools/python/airis) re-exports it with the Gymnasium environments and the
// dataset reader on top.
#include <pybind11/pybind11.h>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "tools/jobs/version.h"  // generated
#include "tools/python/bindings.h"

namespace airis::python {

py::dtype DtypeOf(const RecordLayout& layout) {
  py::list names, formats, offsets;
  for (const RecordField& f : layout.fields()) {
    names.append(f.name);
    formats.append(f.format);
    offsets.append(f.offset);
  }
  py::dict spec;
  spec["names"] = names;
  spec["formats"] = formats;
  spec["offsets"] = offsets;
  spec["itemsize"] = layout.record_bytes();
  return py::dtype::from_args(spec);
}

py::array RecordsArray(std::vector<std::uint8_t> bytes, const py::dtype& dtype) {
  const auto itemsize = static_cast<py::ssize_t>(dtype.itemsize());
  const auto rows = static_cast<py::ssize_t>(bytes.size()) / itemsize;
  auto owner = std::make_shared<std::vector<std::uint8_t>>(std::move(bytes));
  const void* data = owner->data();
  return ViewOf(std::move(owner), dtype, {rows}, {itemsize}, data);
}

bool CheckSignals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  return false;
}

}  // namespace airis::python

PYBIND11_MODULE(_airis, m) {
  namespace py = pybind11;
  using namespace airis;
  m.doc() = "airis: in-process aerial-robot simulation (docs/python.md)";
  m.attr("__version__") = tools::kVersion;
  // airis's errors keep their messages (`file:line:col: key: problem`); ConfigError is a
  // ValueError (bad input), SimulationError a RuntimeError, DatasetIoError an OSError.
  static py::exception<engine::ConfigError> config_error(m, "ConfigError", PyExc_ValueError);
  static py::exception<engine::SimulationError> simulation_error(m, "SimulationError",
                                                                 PyExc_RuntimeError);
  static py::exception<engine::DatasetIoError> io_error(m, "DatasetIoError", PyExc_OSError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const engine::ConfigError& e) {
      config_error(e.what());
    } catch (const engine::InvalidField& e) {
      config_error((e.field() + ": " + e.problem()).c_str());
    } catch (const engine::SimulationError& e) {
      simulation_error(e.what());
    } catch (const engine::DatasetIoError& e) {
      io_error(e.what());
    }
  });
  python::BindTools(m);
  python::BindSensors(m);
  python::BindCameras(m);
  python::BindSimulation(m);
  python::BindVectorEnv(m);
}
