#include "experiments/domain/data/synthetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

class SyntheticTest : public ::testing::Test {
 protected:
  // Small enough to run in milliseconds under ASan, large enough to show the model's structure.
  SyntheticTest() {
    params_.dim = 32;
    params_.place_features = 64;
    training_.environments = 4;
  }
  // The training sets' parameters with `n` samples.
  SyntheticTrainingParams Samples(int n) const {
    SyntheticTrainingParams t = training_;
    t.samples = n;
    return t;
  }
  // `n` frames along a straight road in x, `step` metres apart, all facing `angle` (radians,
  // in the x-z plane).
  static Trajectory Road(int n, double step, double angle = 0.0) {
    Trajectory t{Positions(n, 3), Headings(n, 3)};
    for (int i = 0; i < n; ++i) {
      t.positions.row(i) << step * i, 1.5, 0.0;
      t.headings.row(i) << std::cos(angle), 0.0, std::sin(angle);
    }
    return t;
  }
  static bool SameBytes(const DescriptorMatrix& a, const DescriptorMatrix& b) {
    return a.rows() == b.rows() && a.cols() == b.cols() &&
           std::memcmp(a.data(), b.data(), sizeof(float) * static_cast<std::size_t>(a.size())) == 0;
  }
  static double MeanSquaredDistance(const DescriptorMatrix& a, const DescriptorMatrix& b) {
    return static_cast<double>((a - b).rowwise().squaredNorm().mean());
  }
  SyntheticParams params_;
  SyntheticTrainingParams training_;
};

TEST_F(SyntheticTest, SameSeedSameBytesOtherSeedDiffers) {
  const Trajectory road = Road(50, 1.0);
  EXPECT_TRUE(SameBytes(SyntheticDeployment(road, params_, 7), SyntheticDeployment(road, params_, 7)));
  EXPECT_FALSE(SameBytes(SyntheticDeployment(road, params_, 7), SyntheticDeployment(road, params_, 8)));
  EXPECT_TRUE(SameBytes(SyntheticTrainingDiverse(params_, Samples(90), 7),
                        SyntheticTrainingDiverse(params_, Samples(90), 7)));
  EXPECT_FALSE(SameBytes(SyntheticTrainingDiverse(params_, Samples(90), 7),
                         SyntheticTrainingDiverse(params_, Samples(90), 8)));
  EXPECT_TRUE(SameBytes(SyntheticTrainingDeploymentLike(params_, Samples(90), 7),
                        SyntheticTrainingDeploymentLike(params_, Samples(90), 7)));
  EXPECT_FALSE(SameBytes(SyntheticTrainingDeploymentLike(params_, Samples(90), 7),
                         SyntheticTrainingDeploymentLike(params_, Samples(90), 8)));
}

TEST_F(SyntheticTest, PinnedValuesOfTheDefaultModel) {
  // Changing the model changes every number in docs/synthetic_model.md: re-measure, then re-pin.
  const DescriptorMatrix m = SyntheticDeployment(Road(3, 2.0), SyntheticParams{}, 1);
  ASSERT_EQ(m.cols(), 128);
  EXPECT_NEAR(m(0, 0), -0.621984184, 1e-6);
  EXPECT_NEAR(m(2, 1), 0.39997974, 1e-6);
  EXPECT_NEAR(m(1, 127), -0.0950872675, 1e-6);
}

TEST_F(SyntheticTest, RowsAreUnitLengthWithTheRequestedShape) {
  const DescriptorMatrix sets[] = {SyntheticDeployment(Road(40, 1.0), params_, 1),
                                   SyntheticTrainingDiverse(params_, Samples(41), 1),
                                   SyntheticTrainingDeploymentLike(params_, Samples(42), 1)};
  EXPECT_EQ(sets[0].rows(), 40);
  EXPECT_EQ(sets[1].rows(), 41);
  EXPECT_EQ(sets[2].rows(), 42);
  for (const auto& m : sets) {
    EXPECT_EQ(m.cols(), 32);
    for (Eigen::Index i = 0; i < m.rows(); ++i) ASSERT_NEAR(m.row(i).norm(), 1.0f, 1e-5f);
  }
  EXPECT_EQ(SyntheticTrainingDiverse(params_, Samples(0), 1).rows(), 0);
  EXPECT_THROW(SyntheticTrainingDiverse(params_, Samples(-1), 1), std::invalid_argument);
}

TEST_F(SyntheticTest, NearbyPlacesLookAlikeFarPlacesDoNot) {
  // 400 frames 0.5 m apart: compare frames 1 m apart with frames 100 m apart.
  const DescriptorMatrix m = SyntheticDeployment(Road(400, 0.5), params_, 3);
  const Eigen::Index n = 200;
  const double near = MeanSquaredDistance(m.topRows(n), m.middleRows(2, n));
  const double far = MeanSquaredDistance(m.topRows(n), m.middleRows(200, n));
  EXPECT_LT(near, 0.5 * far) << "near " << near << " far " << far;
}

TEST_F(SyntheticTest, OppositeHeadingsLookDifferent) {
  params_.noise = 0.0;
  params_.appearance_change = 0.0;  // isolate place and heading
  const DescriptorMatrix forward = SyntheticDeployment(Road(100, 3.0, 0.0), params_, 4);
  const DescriptorMatrix backward = SyntheticDeployment(Road(100, 3.0, std::numbers::pi), params_, 4);
  const DescriptorMatrix slight = SyntheticDeployment(Road(100, 3.0, 0.1), params_, 4);
  EXPECT_LT(2.0 * MeanSquaredDistance(forward, slight), MeanSquaredDistance(forward, backward));
}

TEST_F(SyntheticTest, FirstDimensionsCarryMostVariance) {
  const DescriptorMatrix m = SyntheticTrainingDeploymentLike(params_, Samples(400), 5);
  const Eigen::RowVectorXf mean = m.colwise().mean();
  const Eigen::RowVectorXf var = (m.rowwise() - mean).array().square().colwise().mean();
  EXPECT_GT(var.head(4).sum(), var.tail(16).sum());
}

TEST_F(SyntheticTest, DeploymentLikeTrainingSharesTheDeploymentEnvironment) {
  // The deployment's mean descriptor is near the deployment-like set's and far from the diverse
  // set's: what makes diverse-trained routing unbalanced (docs/design.md §8).
  const Eigen::RowVectorXf deploy = SyntheticDeployment(Road(300, 2.0), params_, 6).colwise().mean();
  const Eigen::RowVectorXf like = SyntheticTrainingDeploymentLike(params_, Samples(300), 6).colwise().mean();
  const Eigen::RowVectorXf diverse = SyntheticTrainingDiverse(params_, Samples(300), 6).colwise().mean();
  EXPECT_LT(2.0f * (deploy - like).norm(), (deploy - diverse).norm());
}

// The message starts with the field, so the config reader only prefixes its key path.
template <typename Params>
void ExpectField(const Params& p, const std::string& field) {
  try {
    p.Validate();
    ADD_FAILURE() << field << " accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ": ", 0), 0u) << e.what();
  }
}

// The relative scales stop at 1e6 (1e30 noise made a frame's squares inf and its descriptor NaN).
TEST_F(SyntheticTest, RelativeScalesAcceptTheirBoundsAndRefuseOnePast) {
  const auto error = [](const SyntheticParams& p) -> std::string {
    try {
      p.Validate();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  };
  SyntheticParams p;
  p.noise = 1e6;
  EXPECT_EQ(error(p), "(no error)");
  p.noise = 1e30;
  EXPECT_EQ(error(p), "noise: must be in [0, 1000000], got 1e+30");
  p = {};
  p.appearance_change = 1000000.5;
  EXPECT_EQ(error(p), "appearance_change: must be in [0, 1000000], got 1000000.5");
  p = {};
  p.environment_offset = 0;
  EXPECT_EQ(error(p), "(no error)");
  p.environment_offset = -1;
  EXPECT_EQ(error(p), "environment_offset: must be in [0, 1000000], got -1");
}

TEST_F(SyntheticTest, ValidateNamesTheField) {
  EXPECT_NO_THROW(SyntheticParams{}.Validate());
  SyntheticParams p;
  p.dim = 0;
  ExpectField(p, "dim");
  p = {};
  p.length_scale_max_m = 1.0;  // below the minimum
  ExpectField(p, "length_scale_max_m");
  p = {};
  p.heading_fraction = 1.5;
  ExpectField(p, "heading_fraction");
  p = {};
  p.noise = -0.1;
  ExpectField(p, "noise");
  p = {};
  p.appearance_time_scale_frames = 0.0;
  ExpectField(p, "appearance_time_scale_frames");
  EXPECT_THROW(SyntheticDeployment(Road(2, 1.0), p, 1), std::invalid_argument);
  EXPECT_NO_THROW(SyntheticTrainingParams{}.Validate());
  SyntheticTrainingParams t;
  t.environments = 0;
  ExpectField(t, "environments");
  t = {};
  t.samples = -1;
  ExpectField(t, "samples");
  t = {};
  t.training_area_m = 0.0;
  ExpectField(t, "training_area_m");
  EXPECT_THROW(SyntheticTrainingDiverse(SyntheticParams{}, t, 1), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
