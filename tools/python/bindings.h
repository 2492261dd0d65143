#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "tools/python/sample_buffer.h"

namespace airis::python {

namespace py = pybind11;

/// The parts of the module airis._airis, each defined in its bind_*.cc.
void BindSimulation(py::module_& m);
void BindSensors(py::module_& m);
void BindCameras(py::module_& m);
void BindVectorEnv(py::module_& m);
void BindTools(py::module_& m);

/// A NumPy array over `owner`'s memory at `data` (no copy): the array keeps `owner` alive through
/// a capsule, so the memory lives as long as any view of it.
template <class Owner>
py::array ViewOf(std::shared_ptr<Owner> owner, const py::dtype& dtype,
                 std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                 const void* data) {
  auto* keep = new std::shared_ptr<Owner>(std::move(owner));
  py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<Owner>*>(p); });
  return py::array(dtype, std::move(shape), std::move(strides), data, base);
}

/// The NumPy structured dtype of `layout` (packed, field offsets as the dataset's .npy streams).
py::dtype DtypeOf(const RecordLayout& layout);

/// Packed records as a structured array of `dtype` that owns `bytes` (moved, not copied).
py::array RecordsArray(std::vector<std::uint8_t> bytes, const py::dtype& dtype);

/// Asks Python whether a signal (Ctrl-C) arrived; throws error_already_set (KeyboardInterrupt)
/// when its handler raised. For the long loops of step/run_for/run_mission, with the GIL held.
bool CheckSignals();

}  // namespace airis::python
