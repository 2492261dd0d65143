#include "engine/dataset/dataset_writer.h"

#include <cstdio>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"

namespace airis::engine {
namespace {

std::string FrameName(std::int64_t index) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%06lld", static_cast<long long>(index));
  return buf;
}

void CreateFolder(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) throw DatasetIoError("cannot create folder " + path.string() + ": " + ec.message());
}

}  // namespace

DatasetWriter::DatasetWriter(std::filesystem::path root, Options options)
    : root_(std::move(root)), options_(options) {
  AIRIS_DEMAND(options_.workers >= 1 && options_.max_pending_frames >= 1);
  for (int i = 0; i < options_.workers; ++i) workers_.emplace_back([this] { WorkerLoop(); });
}

DatasetWriter::~DatasetWriter() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (auto& t : workers_) t.join();
}

int DatasetWriter::AddCamera(const std::string& name, const DatasetOutputs& outputs,
                             const TartanAirSlot& tartanair) {
  Camera cam{name, outputs, tartanair, {}};
  const std::filesystem::path dir = root_ / name;
  if (outputs.rgb) CreateFolder(dir / "rgb");
  if (outputs.depth_png || outputs.depth_npy) CreateFolder(dir / "depth");
  if (outputs.segmentation) {
    CreateFolder(dir / "seg_class");
    CreateFolder(dir / "seg_instance");
  }
  if (outputs.normals) CreateFolder(dir / "normals");
  if (outputs.tartanair) {
    AIRIS_DEMAND(!tartanair.trajectory.empty() && !tartanair.side.empty());
    for (const char* kind : {"image", "depth", "seg"}) {
      CreateFolder(TartanAirFramePath(root_, tartanair, kind, 0).parent_path());
    }
  }
  cameras_.push_back(std::move(cam));
  return static_cast<int>(cameras_.size()) - 1;
}

std::filesystem::path DatasetWriter::FramePath(int camera, const char* kind, std::int64_t index,
                                               const char* ext) const {
  return root_ / cameras_[static_cast<std::size_t>(camera)].name / kind / (FrameName(index) + ext);
}

bool DatasetWriter::FrameComplete(int camera, std::int64_t index) const {
  const Camera& cam = cameras_[static_cast<std::size_t>(camera)];
  const DatasetOutputs& o = cam.outputs;
  auto exists = [&](const char* kind, const char* ext) {
    return std::filesystem::exists(FramePath(camera, kind, index, ext));
  };
  auto tartan_exists = [&](const char* kind) {
    return std::filesystem::exists(TartanAirFramePath(root_, cam.tartanair, kind, index));
  };
  return (!o.rgb || exists("rgb", ".png")) && (!o.depth_png || exists("depth", ".png")) &&
         (!o.depth_npy || exists("depth", ".npy")) &&
         (!o.segmentation || (exists("seg_class", ".png") && exists("seg_instance", ".png"))) &&
         (!o.normals || exists("normals", ".npy")) &&
         (!o.tartanair ||
          (tartan_exists("image") && tartan_exists("depth") && tartan_exists("seg")));
}

void DatasetWriter::Adopt(int camera, std::int64_t index) {
  Camera& cam = cameras_[static_cast<std::size_t>(camera)];
  std::vector<InstanceAnnotation> anns;
  if (cam.outputs.segmentation) {
    const auto ids = DecodePng16(ReadFileBytes(FramePath(camera, "seg_instance", index, ".png")));
    const auto cls = DecodePng8(ReadFileBytes(FramePath(camera, "seg_class", index, ".png")));
    anns = ExtractInstanceAnnotations(ids, cls, options_.annotations);
  }
  std::lock_guard lock(mutex_);
  cam.annotations[index] = std::move(anns);
}

void DatasetWriter::Submit(int camera, std::int64_t index,
                           std::shared_ptr<const CameraFrame> frame) {
  std::unique_lock lock(mutex_);
  space_ready_.wait(lock, [&] {
    return error_ || static_cast<int>(queue_.size()) < options_.max_pending_frames;
  });
  if (error_) {
    lock.unlock();
    RethrowWorkerError();
  }
  queue_.push_back({camera, index, std::move(frame)});
  work_ready_.notify_one();
}

void DatasetWriter::Flush() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return (queue_.empty() && busy_ == 0) || error_; });
  lock.unlock();
  RethrowWorkerError();
}

void DatasetWriter::RethrowWorkerError() {
  std::exception_ptr e;
  {
    std::lock_guard lock(mutex_);
    e = error_;
  }
  if (e) std::rethrow_exception(e);
}

void DatasetWriter::WorkerLoop() {
  for (;;) {
    Job job;
    bool failed_before = false;
    {
      std::unique_lock lock(mutex_);
      work_ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping and nothing left
      job = std::move(queue_.front());
      queue_.pop_front();
      ++busy_;
      failed_before = error_ != nullptr;  // after a failure, drain the queue without writing
    }
    space_ready_.notify_one();
    try {
      if (!failed_before) WriteFrame(job);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
    {
      std::lock_guard lock(mutex_);
      --busy_;
    }
    idle_.notify_all();
    space_ready_.notify_all();
  }
}

void DatasetWriter::WriteFrame(const Job& job) {
  const CameraFrame& f = *job.frame;
  const Camera& cam = cameras_[static_cast<std::size_t>(job.camera)];
  const DatasetOutputs& o = cam.outputs;
  auto write = [&](const char* kind, const char* ext, const std::vector<std::uint8_t>& bytes) {
    WriteFileAtomically(FramePath(job.camera, kind, job.index, ext), bytes);
  };
  if (o.tartanair) {
    // Its image is the same PNG as rgb/ (encoded once when both are written).
    const std::vector<std::uint8_t> png = EncodeRgbPng(f.rgba);
    if (o.rgb) write("rgb", ".png", png);
    WriteFileAtomically(TartanAirFramePath(root_, cam.tartanair, "image", job.index), png);
    WriteFileAtomically(TartanAirFramePath(root_, cam.tartanair, "depth", job.index),
                        EncodeNpy(ToTartanAirDepth(f.depth_planar_m)));
    WriteFileAtomically(TartanAirFramePath(root_, cam.tartanair, "seg", job.index),
                        EncodeNpy(f.class_id));
  } else if (o.rgb) {
    write("rgb", ".png", EncodeRgbPng(f.rgba));
  }
  if (o.depth_png) write("depth", ".png", EncodeDepthMmPng(f.depth_planar_m));
  if (o.depth_npy) write("depth", ".npy", EncodeNpy(f.depth_planar_m));
  if (o.normals) write("normals", ".npy", EncodeNpy(f.normal_C));
  std::vector<InstanceAnnotation> anns;
  if (o.segmentation) {
    write("seg_class", ".png", EncodeClassPng(f.class_id));
    write("seg_instance", ".png", EncodeInstancePng(f.instance_id));
    anns = ExtractInstanceAnnotations(f.instance_id, f.class_id, options_.annotations);
  }
  std::lock_guard lock(mutex_);
  cameras_[static_cast<std::size_t>(job.camera)].annotations[job.index] = std::move(anns);
  ++frames_written_;
}

}  // namespace airis::engine
