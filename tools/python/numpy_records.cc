// The NumPy side of packed records and Python's signal check, shared by the bind_*.cc files.
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
