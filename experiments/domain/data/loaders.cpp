#include "experiments/domain/data/loaders.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/domain/data/npy.h"
#include "experiments/domain/data/printable.h"
#include "experiments/domain/data/text_file.h"

namespace dvpr {

namespace fs = std::filesystem;
namespace tf = text_file;  // the text readers shared by loaders.cpp and robot_trajectory.cpp

Trajectory LoadKittiPoses(const fs::path& path) {
  const std::vector<std::string> lines = tf::ReadLines(path);
  const auto n = static_cast<Eigen::Index>(lines.size());
  Trajectory t{Positions(n, 3), Headings(n, 3)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t line = static_cast<std::size_t>(i) + 1;
    const auto tokens = tf::SplitWhitespace(lines[static_cast<std::size_t>(i)]);
    if (tokens.size() != 12) {
      tf::FailLine(path, line, "expected 12 numbers (a 3x4 pose), got " + std::to_string(tokens.size()));
    }
    double v[12];
    for (int k = 0; k < 12; ++k) v[k] = tf::ParseNumber(path, line, tokens[static_cast<std::size_t>(k)]);
    for (const int k : {3, 7, 11}) {
      if (std::abs(v[k]) > kMaxPoseTranslation_m) {
        tf::FailLine(path, line, "translation " + std::string(tf::Trim(tokens[static_cast<std::size_t>(k)])) +
                                 " m is outside [-1e9, 1e9] m");
      }
    }
    t.positions.row(i) << v[3], v[7], v[11];
    t.headings.row(i) << v[2], v[6], v[10];
    double norm = t.headings.row(i).norm();
    if (!std::isfinite(norm)) {
      // norm() squares: a column of 1e200 overflows to inf (and gave a zero heading). Scaling by
      // the largest value first fixes it; ordinary headings do not come here and keep their bits.
      t.headings.row(i) /= t.headings.row(i).cwiseAbs().maxCoeff();
      norm = t.headings.row(i).norm();
    }
    if (norm < 1e-6) tf::FailLine(path, line, "rotation's third column is zero (no heading)");
    if (!std::isfinite(norm)) tf::FailLine(path, line, "rotation's third column is too large to normalise");
    t.headings.row(i) /= norm;
  }
  return t;
}

void CheckDescriptorValues(const DescriptorMatrix& m, const std::string& source) {
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (!m.row(i).allFinite()) {
      throw std::runtime_error(source + ": frame " + std::to_string(i) +
                               " (0-based row) holds NaN or Inf");
    }
    if (m.row(i).cwiseAbs().maxCoeff() > kMaxDescriptorValue) {
      throw std::runtime_error(source + ": frame " + std::to_string(i) +
                               " (0-based row) holds a value outside [-1e9, 1e9]");
    }
    if ((m.row(i).array() == 0.0f).all()) {
      throw std::runtime_error(source + ": frame " + std::to_string(i) +
                               " (0-based row) is an all-zero vector");
    }
  }
}

namespace {

void CheckDim(const fs::path& path, int dim, Eigen::Index width) {
  if (dim <= 0) tf::Fail(path, "dim must be positive, got " + std::to_string(dim));
  if (dim > width) {
    tf::Fail(path, "dim " + std::to_string(dim) + " is larger than the file's " +
                   std::to_string(width) + " values per frame");
  }
}

DescriptorMatrix LoadBin(const fs::path& path, int dim, int frame_width) {
  if (frame_width <= 0) {
    tf::Fail(path, "bin_frame_width must be positive, got " + std::to_string(frame_width));
  }
  CheckDim(path, dim, frame_width);
  if (const std::string why = tf::ThereButNotARegularFile(path); !why.empty()) tf::Fail(path, why);
  std::ifstream in(path, std::ios::binary);
  if (!in) tf::Fail(path, "cannot open for reading");
  const std::uintmax_t bytes = fs::file_size(path);
  const std::uintmax_t frame_bytes = static_cast<std::uintmax_t>(frame_width) * sizeof(float);
  if (bytes % frame_bytes != 0) {
    tf::Fail(path, "size " + std::to_string(bytes) + " bytes is not a multiple of one frame (" +
                   std::to_string(frame_width) + " float32 = " + std::to_string(frame_bytes) +
                   " bytes): truncated, or the wrong bin_frame_width");
  }
  const auto frames = static_cast<Eigen::Index>(bytes / frame_bytes);
  DescriptorMatrix m(frames, dim);
  std::vector<float> frame(static_cast<std::size_t>(frame_width));
  for (Eigen::Index i = 0; i < frames; ++i) {
    if (!in.read(reinterpret_cast<char*>(frame.data()), static_cast<std::streamsize>(frame_bytes))) {
      tf::Fail(path, "read error at frame " + std::to_string(i));
    }
    std::copy_n(frame.data(), dim, &m(i, 0));
  }
  return m;
}

DescriptorMatrix LoadCsv(const fs::path& path, int dim, Eigen::Index& width) {
  const std::vector<std::string> lines = tf::ReadLines(path);
  width = static_cast<Eigen::Index>(tf::SplitCommas(lines.front()).size());
  CheckDim(path, dim, width);
  DescriptorMatrix m(static_cast<Eigen::Index>(lines.size()), dim);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto fields = tf::SplitCommas(lines[i]);
    if (static_cast<Eigen::Index>(fields.size()) != width) {
      tf::FailLine(path, i + 1, "expected " + std::to_string(width) + " values (as on line 1), got " +
                                std::to_string(fields.size()));
    }
    for (int j = 0; j < dim; ++j) {
      m(static_cast<Eigen::Index>(i), j) =
          static_cast<float>(tf::ParseNumber(path, i + 1, fields[static_cast<std::size_t>(j)]));
    }
  }
  return m;
}

std::string LowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

DescriptorFile LoadDescriptorFile(const fs::path& path, int dim, int bin_frame_width) {
  const std::string ext = LowerExtension(path);
  DescriptorFile file;
  if (ext == ".npy") {
    DescriptorMatrix all = ReadNpyMatrix(path);
    CheckDim(path, dim, all.cols());
    file.width = all.cols();
    file.rows = all.leftCols(dim);
  } else if (ext == ".bin") {
    file.rows = LoadBin(path, dim, bin_frame_width);
    file.width = bin_frame_width;
  } else if (ext == ".csv") {
    file.rows = LoadCsv(path, dim, file.width);
  } else {
    tf::Fail(path, "unknown descriptor file extension '" + ext + "' (expected .npy, .bin or .csv)");
  }
  if (file.rows.rows() == 0) tf::Fail(path, "holds no frames");
  CheckDescriptorValues(file.rows, path.string());
  return file;
}

DescriptorMatrix LoadDescriptors(const fs::path& path, int dim, int bin_frame_width) {
  return LoadDescriptorFile(path, dim, bin_frame_width).rows;
}

void DatasetFiles::Validate() const {
  const auto bad = [](const std::string& field, const std::string& why) {
    throw std::invalid_argument("dataset." + field + ": " + why);
  };
  if (poses.empty()) bad("poses", "no pose file given");
  if (descriptors.empty()) bad("descriptors", "no descriptor file given");
  if (dim <= 0) bad("dim", "must be positive, got " + std::to_string(dim));
  if (bin_frame_width <= 0) bad("bin_frame_width", "must be positive");
  if (!(fps > 0.0) || !std::isfinite(fps)) bad("fps", "must be positive and finite");
  if (frames == 0 || frames < -1) bad("frames", "must be a positive count or -1 (all)");
}

void CheckSameFrameCount(const Trajectory& trajectory, const fs::path& poses, const DescriptorMatrix& descriptors,
                         const fs::path& descriptor_file) {
  if (trajectory.size() != descriptors.rows()) {
    throw std::runtime_error("frame count mismatch: pose file " + poses.string() + " has " +
                             std::to_string(trajectory.size()) + " frames, descriptor file " +
                             descriptor_file.string() + " has " + std::to_string(descriptors.rows()));
  }
}

void KeepFirstFrames(Trajectory& trajectory, int frames, const fs::path& poses) {
  if (frames < 0) return;
  if (frames > trajectory.size()) {
    throw std::runtime_error(std::to_string(frames) + " frames requested, but the pose file " + poses.string() +
                             " has only " + std::to_string(trajectory.size()));
  }
  trajectory.positions.conservativeResize(frames, Eigen::NoChange);
  trajectory.headings.conservativeResize(frames, Eigen::NoChange);
}

Dataset LoadDataset(const DatasetFiles& files) {
  files.Validate();
  Trajectory trajectory = LoadKittiPoses(files.poses);
  DescriptorMatrix descriptors = LoadDescriptors(files.descriptors, files.dim, files.bin_frame_width);
  CheckSameFrameCount(trajectory, files.poses, descriptors, files.descriptors);
  try {
    KeepFirstFrames(trajectory, files.frames, files.poses);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("dataset.frames: ") + e.what());
  }
  descriptors.conservativeResize(trajectory.size(), Eigen::NoChange);
  std::string name = files.name.empty() ? files.descriptors.stem().string() : files.name;
  return Dataset{std::move(name), std::move(trajectory), std::move(descriptors), files.fps};
}

}  // namespace dvpr
