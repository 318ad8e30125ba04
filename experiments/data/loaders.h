#pragma once
// Loading deployment data from files: KITTI pose files and descriptor matrices (.npy, .bin, .csv).
// Every malformed input is a std::runtime_error naming the file and, where it applies, the line
// (1-based, text files) or frame (0-based row index) at fault.
#include <filesystem>
#include <string>

#include "agents/descriptors.h"
#include "experiments/data/dataset.h"

namespace dvpr {

// KITTI odometry ground truth: one pose per line, 12 numbers (row-major 3x4 [R|t]). Positions are
// values 4, 8, 12 (1-based); headings are values 3, 7, 11 (the camera's z axis), normalised.
Trajectory LoadKittiPoses(const std::filesystem::path& path);

// Descriptors, one row per frame, by extension:
//   .npy  2-D float32/float64 (see ReadNpyMatrix);
//   .bin  raw little-endian float32, `bin_frame_width` values per frame, frames back to back
//         (the authors' NetVLAD dumps: 4096 per frame);
//   .csv  one frame per line, values separated by commas.
// Only the first `dim` columns are kept (descriptors are PCA-ordered). Rejects dim larger than
// the file's width, no frames, NaN/Inf and all-zero vectors (within the kept columns).
DescriptorMatrix LoadDescriptors(const std::filesystem::path& path, int dim,
                                 int bin_frame_width = 4096);

// Throws if a row holds NaN/Inf or is all zeros; `source` names where the matrix came from.
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

// Loads both files and checks that they hold the same number of frames.
Dataset LoadDataset(const DatasetFiles& files);

}  // namespace dvpr
