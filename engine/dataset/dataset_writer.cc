#include "engine/dataset/dataset_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "engine/core/error.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/image_encoding.h"
#include "engine/dataset/pcd_file.h"
#include "engine/dataset/sha256.h"

namespace airis::engine {
namespace {

std::string FrameName(std::int64_t index) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%06lld", static_cast<long long>(index));
  return buf;
}

constexpr const char* kJournal = "checksums.journal";
constexpr const char* kChecksums = "checksums.csv";

FileChecksum ChecksumOf(std::span<const std::uint8_t> bytes) {
  return {static_cast<std::int64_t>(bytes.size()), Sha256Hex(bytes)};
}

// Parses "path,bytes,sha256" lines into `out`; a torn last line (no newline) is skipped when
// `torn_tail_ok` (an interrupted run's journal). Throws DatasetIoError naming the line.
void ParseChecksums(const std::filesystem::path& file, const std::string& text, bool header,
                    bool torn_tail_ok, std::map<std::string, FileChecksum>* out) {
  std::size_t line_no = 0, start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    ++line_no;
    if (end == std::string::npos && torn_tail_ok) return;
    const std::string line =
        text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    start = end == std::string::npos ? text.size() : end + 1;
    if (header && line_no == 1) continue;
    const std::size_t a = line.find(','), b = line.rfind(',');
    char* stop = nullptr;
    const long long bytes = a != b ? std::strtoll(line.c_str() + a + 1, &stop, 10) : -1;
    if (a == std::string::npos || a == b || bytes < 0 || stop != line.c_str() + b ||
        line.size() - b - 1 != 64) {
      throw DatasetIoError(file.string() + ":" + std::to_string(line_no) +
                           ": not a 'path,bytes,sha256' line");
    }
    (*out)[line.substr(0, a)] = {bytes, line.substr(b + 1)};
  }
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
  if (journal_) std::fclose(journal_);
}

int DatasetWriter::AddCamera(const std::string& name, const DatasetOutputs& outputs,
                             const TartanAirSlot& tartanair, double depth_unit_m) {
  AIRIS_DEMAND(depth_unit_m > 0.0);
  Camera cam{name, outputs, tartanair, depth_unit_m, {}, 0};
  (void)PathUnder(root_, name);  // its folders are made when its first frame is written
  AIRIS_DEMAND(!outputs.tartanair || (!tartanair.trajectory.empty() && !tartanair.side.empty()));
  cameras_.push_back(std::move(cam));
  return static_cast<int>(cameras_.size()) - 1;
}

int DatasetWriter::AddScanner(const std::string& folder) {
  (void)PathUnder(root_, folder);  // its folder is made when its first scan is written
  scanners_.push_back({folder, {}});
  return static_cast<int>(scanners_.size()) - 1;
}

std::filesystem::path DatasetWriter::ScanFile(int scanner, std::int64_t index) const {
  return std::filesystem::path(scanners_[static_cast<std::size_t>(scanner)].folder) /
         (FrameName(index) + ".pcd");
}

std::filesystem::path DatasetWriter::FramePath(int camera, const char* kind, std::int64_t index,
                                               const char* ext) const {
  return root_ / cameras_[static_cast<std::size_t>(camera)].name / kind / (FrameName(index) + ext);
}

std::vector<std::filesystem::path> DatasetWriter::FrameFiles(int camera, std::int64_t index) const {
  const Camera& cam = cameras_[static_cast<std::size_t>(camera)];
  const DatasetOutputs& o = cam.outputs;
  const std::filesystem::path dir = cam.name;
  const std::string n = FrameName(index);
  std::vector<std::filesystem::path> files;
  if (o.rgb) files.push_back(dir / "rgb" / (n + ".png"));
  if (o.depth_png) files.push_back(dir / "depth" / (n + ".png"));
  if (o.depth_npy) files.push_back(dir / "depth" / (n + ".npy"));
  if (o.segmentation) {
    files.push_back(dir / "seg_class" / (n + ".png"));
    files.push_back(dir / "seg_instance" / (n + ".png"));
  }
  if (o.normals) files.push_back(dir / "normals" / (n + ".npy"));
  if (o.tartanair) {
    for (const char* kind : {"image", "depth", "seg"}) {
      files.push_back(
          std::filesystem::relative(TartanAirFramePath(root_, cam.tartanair, kind, index), root_));
    }
  }
  return files;
}

void DatasetWriter::LoadRecordedChecksums() {
  recorded_.clear();
  const std::filesystem::path final_list = root_ / kChecksums;
  if (std::filesystem::exists(final_list)) {
    const auto bytes = ReadFileBytes(final_list);
    ParseChecksums(final_list, std::string(bytes.begin(), bytes.end()), true, false, &recorded_);
  }
  const std::filesystem::path journal = root_ / kJournal;
  if (std::filesystem::exists(journal)) {
    const auto bytes = ReadFileBytes(journal);
    ParseChecksums(journal, std::string(bytes.begin(), bytes.end()), false, true, &recorded_);
  }
}

bool DatasetWriter::VerifyFiles(const std::vector<std::filesystem::path>& files,
                                std::string* why) const {
  for (const std::filesystem::path& rel : files) {
    const auto fail = [&](const std::string& what) {
      if (why) *why = rel.string() + ": " + what;
      return false;
    };
    const auto it = recorded_.find(rel.string());
    const std::filesystem::path path = root_ / rel;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return fail("missing");
    if (it == recorded_.end()) return fail("no checksum was recorded for it");
    const auto size = static_cast<std::int64_t>(std::filesystem::file_size(path, ec));
    if (ec || size != it->second.bytes) {
      return fail(std::to_string(size) + " bytes, written with " +
                  std::to_string(it->second.bytes));
    }
    if (Sha256Hex(ReadFileBytes(path)) != it->second.sha256) {
      return fail("its content changed since it was written (SHA-256 differs)");
    }
  }
  return true;
}

void DatasetWriter::AdoptFiles(const std::vector<std::filesystem::path>& files) {
  std::vector<std::pair<std::filesystem::path, FileChecksum>> recorded;
  for (const std::filesystem::path& rel : files) {
    const auto it = recorded_.find(rel.string());
    AIRIS_DEMAND(it != recorded_.end());  // VerifyFiles first
    recorded.emplace_back(rel, it->second);
  }
  Record(recorded);
}

bool DatasetWriter::VerifyFrame(int camera, std::int64_t index, std::string* why) const {
  return VerifyFiles(FrameFiles(camera, index), why);
}

void DatasetWriter::Adopt(int camera, std::int64_t index) {
  Camera& cam = cameras_[static_cast<std::size_t>(camera)];
  AdoptFiles(FrameFiles(camera, index));
  std::vector<InstanceAnnotation> anns;
  if (cam.outputs.segmentation) {
    const auto ids =
        DecodeInstancePng(ReadFileBytes(FramePath(camera, "seg_instance", index, ".png")));
    const auto cls = DecodePng8(ReadFileBytes(FramePath(camera, "seg_class", index, ".png")));
    anns = ExtractInstanceAnnotations(ids, cls, options_.annotations);
  }
  std::lock_guard lock(mutex_);
  cam.annotations[index] = std::move(anns);
}

bool DatasetWriter::VerifyScan(int scanner, std::int64_t index, std::string* why) const {
  return VerifyFiles({ScanFile(scanner, index)}, why);
}

void DatasetWriter::AdoptScan(int scanner, std::int64_t index) {
  AdoptFiles({ScanFile(scanner, index)});
  std::lock_guard lock(mutex_);
  scanners_[static_cast<std::size_t>(scanner)].written.insert(index);
}

void DatasetWriter::Submit(int camera, std::int64_t index,
                           std::shared_ptr<const CameraFrame> frame) {
  Job job;
  job.camera = camera;
  job.index = index;
  job.frame = std::move(frame);
  Enqueue(std::move(job));
}

void DatasetWriter::SubmitScan(int scanner, std::int64_t index,
                               std::shared_ptr<const PointCloudSample> scan) {
  Job job;
  job.scanner = scanner;
  job.index = index;
  job.scan = std::move(scan);
  Enqueue(std::move(job));
}

void DatasetWriter::Enqueue(Job job) {
  std::unique_lock lock(mutex_);
  space_ready_.wait(lock, [&] {
    return error_ || static_cast<int>(queue_.size()) < options_.max_pending_frames;
  });
  if (error_) {
    lock.unlock();
    RethrowWorkerError();
  }
  queue_.push_back(std::move(job));
  work_ready_.notify_one();
}

void DatasetWriter::Flush() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return (queue_.empty() && busy_ == 0) || error_; });
  lock.unlock();
  RethrowWorkerError();
}

void DatasetWriter::Record(
    const std::vector<std::pair<std::filesystem::path, FileChecksum>>& files) {
  std::lock_guard lock(mutex_);
  if (!journal_) {
    const std::filesystem::path path = root_ / kJournal;
    journal_ = std::fopen(path.c_str(), "a");
    if (!journal_) {
      throw DatasetIoError("cannot open " + path.string() + ": " + std::strerror(errno));
    }
  }
  std::string lines;
  for (const auto& [rel, sum] : files) {
    checksums_[rel.string()] = sum;
    lines += rel.string() + "," + std::to_string(sum.bytes) + "," + sum.sha256 + "\n";
  }
  // Flushed per frame: a killed run keeps the record of every frame it finished.
  if (std::fwrite(lines.data(), 1, lines.size(), journal_) != lines.size() ||
      std::fflush(journal_) != 0) {
    throw DatasetIoError("cannot write " + (root_ / kJournal).string() + ": " +
                         std::strerror(errno));
  }
}

void DatasetWriter::WriteChecksums() {
  std::lock_guard lock(mutex_);
  std::string text = "path,bytes,sha256\n";
  for (const auto& [rel, sum] : checksums_) {
    text += rel + "," + std::to_string(sum.bytes) + "," + sum.sha256 + "\n";
  }
  WriteFileAtomically(root_ / kChecksums, text);
  if (journal_) {
    std::fclose(journal_);
    journal_ = nullptr;
  }
  std::error_code ec;
  std::filesystem::remove(root_ / kJournal, ec);
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
      if (!failed_before && job.scan) WriteScan(job);
      if (!failed_before && job.frame) WriteFrame(job);
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

void DatasetWriter::WriteScan(const Job& job) {
  const std::filesystem::path rel = ScanFile(job.scanner, job.index);
  const std::vector<std::uint8_t> bytes = EncodeScanPcd(*job.scan);
  CreateFolder((root_ / rel).parent_path());
  WriteFileAtomically(root_ / rel, bytes);
  Record({{rel, ChecksumOf(bytes)}});
  std::lock_guard lock(mutex_);
  scanners_[static_cast<std::size_t>(job.scanner)].written.insert(job.index);
}

void DatasetWriter::WriteFrame(const Job& job) {
  const CameraFrame& f = *job.frame;
  const Camera& cam = cameras_[static_cast<std::size_t>(job.camera)];
  const DatasetOutputs& o = cam.outputs;
  std::vector<std::pair<std::filesystem::path, FileChecksum>> written;
  auto write = [&](const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    CreateFolder(path.parent_path());
    WriteFileAtomically(path, bytes);
    written.emplace_back(std::filesystem::relative(path, root_), ChecksumOf(bytes));
  };
  if (o.tartanair) {
    // Its image is the same PNG as rgb/ (encoded once when both are written).
    const std::vector<std::uint8_t> png = EncodeRgbPng(f.rgba);
    if (o.rgb) write(FramePath(job.camera, "rgb", job.index, ".png"), png);
    write(TartanAirFramePath(root_, cam.tartanair, "image", job.index), png);
    write(TartanAirFramePath(root_, cam.tartanair, "depth", job.index),
          EncodeNpy(ToTartanAirDepth(f.depth_planar_m)));
    write(TartanAirFramePath(root_, cam.tartanair, "seg", job.index), EncodeNpy(f.class_id));
  } else if (o.rgb) {
    write(FramePath(job.camera, "rgb", job.index, ".png"), EncodeRgbPng(f.rgba));
  }
  std::int64_t clipped = 0;
  if (o.depth_png) {
    write(FramePath(job.camera, "depth", job.index, ".png"),
          EncodeDepthPng(f.depth_planar_m, cam.depth_unit_m, &clipped));
  }
  if (o.depth_npy)
    write(FramePath(job.camera, "depth", job.index, ".npy"), EncodeNpy(f.depth_planar_m));
  if (o.normals) write(FramePath(job.camera, "normals", job.index, ".npy"), EncodeNpy(f.normal_C));
  std::vector<InstanceAnnotation> anns;
  if (o.segmentation) {
    write(FramePath(job.camera, "seg_class", job.index, ".png"), EncodeClassPng(f.class_id));
    write(FramePath(job.camera, "seg_instance", job.index, ".png"),
          EncodeInstancePng(f.instance_id, o.instance_format));
    anns = ExtractInstanceAnnotations(f.instance_id, f.class_id, options_.annotations);
  }
  Record(written);
  std::lock_guard lock(mutex_);
  Camera& mutable_cam = cameras_[static_cast<std::size_t>(job.camera)];
  mutable_cam.annotations[job.index] = std::move(anns);
  mutable_cam.clipped_depth_pixels += clipped;
  ++frames_written_;
}

}  // namespace airis::engine
