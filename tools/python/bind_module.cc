// The extension module airis._airis: exceptions, then the parts in bind_*.cc. The pure-Python
// package airis (tools/python/airis) re-exports it with the Gymnasium environments and the
// dataset reader on top.
#include <pybind11/pybind11.h>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "engine/mavlink/link/link.h"
#include "tools/jobs/version.h"  // generated
#include "tools/python/bindings.h"

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
  // PX4 did not connect, closed its link or stopped answering (docs/px4.md).
  static py::exception<engine::mavlink::LinkError> link_error(m, "AutopilotLinkError",
                                                              PyExc_ConnectionError);
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
    } catch (const engine::mavlink::LinkError& e) {
      link_error(e.what());
    }
  });
  python::BindTools(m);
  python::BindSensors(m);
  python::BindCameras(m);
  python::BindSimulation(m);
  python::BindVectorEnv(m);
}
