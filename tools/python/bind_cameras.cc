// airis.Camera and airis.Frame: images rendered on demand, as NumPy views of the frame's own
// buffers (the GPU readback is the only copy).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <memory>
#include <vector>

#include "engine/world/image_sensor.h"
#include "tools/python/bindings.h"
#include "tools/python/handles.h"

namespace airis::python {
namespace {

// The frames of one capture, shared by the Frame objects and every array viewing them.
using Frames = std::vector<engine::CameraFrame>;

struct FrameHandle {
  std::shared_ptr<Frames> frames;
  std::size_t index = 0;
  engine::ImageStream stream;

  const engine::CameraFrame& get() const { return (*frames)[index]; }
};

struct StereoFrameHandle {
  FrameHandle left, right;
  double baseline_m = 0.0;
};

// A camera of a vehicle and the buffers of its last capture (reused when nothing views them).
struct CameraHandle {
  SensorHandle sensor;
  std::shared_ptr<Frames> last;

  engine::ImageSensor& get() const { return *sensor.get().image(); }
};

template <class T>
py::object View(const FrameHandle& f, const engine::Image<T>& image, int channels_shown) {
  if (image.empty()) return py::none();
  const auto h = static_cast<py::ssize_t>(image.height);
  const auto w = static_cast<py::ssize_t>(image.width);
  const auto c = static_cast<py::ssize_t>(image.channels);
  const auto item = static_cast<py::ssize_t>(sizeof(T));
  std::vector<py::ssize_t> shape{h, w}, strides{w * c * item, c * item};
  if (channels_shown > 1) {
    shape.push_back(channels_shown);
    strides.push_back(item);
  }
  return ViewOf(f.frames, py::dtype::of<T>(), shape, strides, image.pixels.data());
}

py::dict Intrinsics(const engine::CameraIntrinsics& k) {
  py::dict d;
  d["width_px"] = k.width_px;
  d["height_px"] = k.height_px;
  d["fx_px"] = k.fx_px;
  d["fy_px"] = k.fy_px;
  d["cx_px"] = k.cx_px;
  d["cy_px"] = k.cy_px;
  d["near_m"] = k.near_m;
  d["far_m"] = k.far_m;
  d["distortion_k1_k2_p1_p2_k3"] = std::vector<double>{
      k.distortion.k1, k.distortion.k2, k.distortion.p1, k.distortion.p2, k.distortion.k3};
  return d;
}

Eigen::Matrix3d KMatrix(const engine::CameraIntrinsics& k) {
  Eigen::Matrix3d K;
  K << k.fx_px, 0.0, k.cx_px, 0.0, k.fy_px, k.cy_px, 0.0, 0.0, 1.0;
  return K;
}

py::object Capture(CameraHandle& cam) {
  engine::ImageSensor& sensor = cam.get();
  const auto streams = sensor.streams();
  // Reuse the last capture's buffers only when no Frame or array still views them.
  if (!cam.last || cam.last.use_count() > 1) cam.last = std::make_shared<Frames>(streams.size());
  PythonSimulation& sim = *cam.sensor.sim;
  engine::World& w = sim.world();
  const std::size_t v = cam.sensor.vehicle;
  const engine::SensorContext context{sim.simulation().clock().now_ns(),
                                      &w.vehicle(v).state(),
                                      &w.accelerations(v),
                                      &w.environment(),
                                      w.ray_caster(),
                                      &w,
                                      v};
  sensor.Capture(context, *cam.last);
  std::vector<FrameHandle> frames;
  for (std::size_t i = 0; i < streams.size(); ++i) frames.push_back({cam.last, i, streams[i]});
  if (frames.size() == 1) return py::cast(frames[0]);
  return py::cast(StereoFrameHandle{frames[0], frames[1], streams[1].baseline_m});
}

}  // namespace

void BindCameras(py::module_& m) {
  py::class_<FrameHandle>(m, "Frame",
                          "One rendered image stream at time_ns. Image arrays view the frame's "
                          "buffers (no copy; read-only use expected); None where the camera does "
                          "not render that output")
      .def_property_readonly("stream", [](const FrameHandle& f) { return f.stream.name; })
      .def_property_readonly("time_ns", [](const FrameHandle& f) { return f.get().time_ns; })
      .def_property_readonly(
          "time_s", [](const FrameHandle& f) { return engine::ToSeconds(f.get().time_ns); })
      .def_property_readonly(
          "rgb", [](const FrameHandle& f) { return View(f, f.get().rgba, 3); },
          "(H, W, 3) uint8 sRGB: a strided view of the RGBA buffer")
      .def_property_readonly("rgba", [](const FrameHandle& f) { return View(f, f.get().rgba, 4); })
      .def_property_readonly(
          "depth", [](const FrameHandle& f) { return View(f, f.get().depth_planar_m, 1); },
          "(H, W) float32 metres along the optical axis; inf where the sky is seen")
      .def_property_readonly(
          "depth_perspective",
          [](const FrameHandle& f) { return View(f, f.get().depth_perspective_m, 1); },
          "(H, W) float32 metres along each pixel's ray; inf for sky")
      .def_property_readonly(
          "class_id", [](const FrameHandle& f) { return View(f, f.get().class_id, 1); },
          "(H, W) uint8 semantic class (0 sky)")
      .def_property_readonly(
          "instance_id", [](const FrameHandle& f) { return View(f, f.get().instance_id, 1); },
          "(H, W) uint32 instance (0 sky)")
      .def_property_readonly(
          "normals", [](const FrameHandle& f) { return View(f, f.get().normal_C, 3); },
          "(H, W, 3) float32 unit normals in the optical frame (0 for sky)")
      .def_property_readonly(
          "T_WC", [](const FrameHandle& f) { return Eigen::Matrix4d(f.get().T_WC.matrix()); },
          "4x4 pose of the optical frame (x right, y down, z forward) in world NED at exposure")
      .def_property_readonly("intrinsics",
                             [](const FrameHandle& f) { return Intrinsics(f.stream.intrinsics); })
      .def_property_readonly("K", [](const FrameHandle& f) { return KMatrix(f.stream.intrinsics); })
      .def("__repr__", [](const FrameHandle& f) {
        return "<airis.Frame '" + f.stream.name + "' " +
               std::to_string(f.stream.intrinsics.width_px) + "x" +
               std::to_string(f.stream.intrinsics.height_px) +
               " t=" + std::to_string(engine::ToSeconds(f.get().time_ns)) + " s>";
      });

  py::class_<StereoFrameHandle>(m, "StereoFrame", "The two eyes of a stereo pair, same instant")
      .def_readonly("left", &StereoFrameHandle::left)
      .def_readonly("right", &StereoFrameHandle::right)
      .def_readonly("baseline_m", &StereoFrameHandle::baseline_m);

  py::class_<CameraHandle>(m, "Camera", "A camera (or stereo pair) of a vehicle")
      .def(py::init([](const SensorHandle& s) {
        if (!s.get().image()) throw py::type_error("sensor '" + s.get().name() + "' is no camera");
        return CameraHandle{s, nullptr};
      }))
      .def_property_readonly("name", [](const CameraHandle& c) { return c.sensor.get().name(); })
      .def_property_readonly("stereo",
                             [](const CameraHandle& c) { return c.get().streams().size() == 2; })
      .def_property_readonly("streams",
                             [](const CameraHandle& c) {
                               std::vector<std::string> out;
                               for (const auto& s : c.get().streams()) out.push_back(s.name);
                               return out;
                             })
      .def_property_readonly("rate_hz",
                             [](const CameraHandle& c) { return c.get().schedule().rate_hz(); })
      .def_property_readonly(
          "intrinsics",
          [](const CameraHandle& c) { return Intrinsics(c.get().streams()[0].intrinsics); })
      .def_property_readonly("outputs",
                             [](const CameraHandle& c) {
                               const engine::RenderOutputs& o = c.get().streams()[0].outputs;
                               py::dict d;
                               d["rgb"] = o.rgb;
                               d["depth_planar"] = o.depth_planar;
                               d["depth_perspective"] = o.depth_perspective;
                               d["segmentation"] = o.segmentation;
                               d["normals"] = o.normals;
                               return d;
                             })
      .def_property_readonly("renderer",
                             [](const CameraHandle& c) { return c.get().renderer().gl_renderer; })
      .def("capture", &Capture,
           "Renders the camera now, from the vehicle's current state: a Frame (a StereoFrame for "
           "a stereo pair)")
      .def("__repr__",
           [](const CameraHandle& c) { return "<airis.Camera '" + c.sensor.get().name() + "'>"; });
}

}  // namespace airis::python
