#pragma once
// Loading deployment data from files: KITTI pose files and descriptor matrices (.npy, .bin, .csv).
// Every malformed input is a std::runtime_error naming the file and, where it applies, the line
// (1-based, text files) or frame (0-based row index) at fault.
#include <filesystem>
#include <string>

#include "agents/algorithms/descriptors.h"
#include "experiments/domain/data/dataset.h"

namespace dvpr {

// The largest magnitudes a data file may hold, so that every squared distance computed from them
// (positions in double, descriptors in float, 4096 dimensions) and every grid cell index of the
// metrics stay far from overflow. Real data is many orders below: KITTI positions are within a few
// km, NetVLAD descriptors are unit vectors.
inline constexpr double kMaxPoseTranslation_m = 1e9;
inline constexpr float kMaxDescriptorValue = 1e9f;

// KITTI odometry ground truth: one pose per line, 12 numbers (row-major 3x4 [R|t]). Positions are
// values 4, 8, 12 (1-based), each within +-kMaxPoseTranslation_m; headings are values 3, 7, 11
// (the camera's z axis), normalised.
Trajectory LoadKittiPoses(const std::filesystem::path& path);

// Descriptors, one row per frame, by extension:
//   .npy  2-D float32/float64 (see ReadNpyMatrix);
//   .bin  raw little-endian float32, `bin_frame_width` values per frame, frames back to back
//         (the authors' NetVLAD dumps: 4096 per frame);
//   .csv  one frame per line, values separated by commas.
// Only the first `dim` columns are kept (descriptors are PCA-ordered). Rejects dim larger than
// the file's width, no frames, NaN/Inf, values beyond +-kMaxDescriptorValue and all-zero vectors
// (within the kept columns).
DescriptorMatrix LoadDescriptors(const std::filesystem::path& path, int dim,
                                 int bin_frame_width = 4096);

// LoadDescriptors' rows and the file's width (values per frame before the first `dim` are kept:
// an .npy's columns, a .csv's values a line, `bin_frame_width` for .bin), so that files meant to
// hold the same kind of descriptor (a team's, one per robot) can be compared.
struct DescriptorFile {
  DescriptorMatrix rows;
  Eigen::Index width = 0;
};
DescriptorFile LoadDescriptorFile(const std::filesystem::path& path, int dim, int bin_frame_width = 4096);

// Throws if a row holds NaN/Inf, a value beyond +-kMaxDescriptorValue or only zeros; `source`
// names where the matrix came from.
void CheckDescriptorValues(const DescriptorMatrix& m, const std::string& source);

struct DatasetFiles {
  std::string name;                  // empty: the descriptor file's stem
  std::filesystem::path poses;       // KITTI pose file
  std::filesystem::path descriptors; // .npy, .bin or .csv
  int dim = 128;
  int bin_frame_width = 4096;
  double fps = 10.0;
  int frames = -1;                   // use only the first `frames` frames; -1: all
  void Validate() const;             // throws naming the offending field
};

// Throws "frame count mismatch: ..." naming both files when they hold different numbers of frames.
void CheckSameFrameCount(const Trajectory& trajectory, const std::filesystem::path& poses,
                         const DescriptorMatrix& descriptors, const std::filesystem::path& descriptor_file);

// Keeps the first `frames` poses (-1: all). A pose file with fewer is an error naming it, never a
// shorter run than asked for: "<frames> frames requested, but the pose file <poses> has only <n>".
void KeepFirstFrames(Trajectory& trajectory, int frames, const std::filesystem::path& poses);

// Loads both files and checks that they hold the same number of frames. Error messages name the
// file; a bad `frames` is "dataset.frames: ...". Callers that label errors by config key (the
// experiments' inputs) load the pieces themselves with the functions above.
Dataset LoadDataset(const DatasetFiles& files);

}  // namespace dvpr
