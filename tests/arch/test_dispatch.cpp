// The generic executable's choice (experiments/arch/dispatch.h), case by case, and, in a build
// with DVPR_ARCH=dispatch, what `dvpr --version` says each way.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "experiments/arch/dispatch.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

TEST(ChooseVariantTest, FastWhenTheCpuRunsItAndTheSiblingIsThere) {
  EXPECT_TRUE(ChooseVariant(true, true, nullptr).exec_fast);
  EXPECT_TRUE(ChooseVariant(true, true, "").exec_fast);
  EXPECT_TRUE(ChooseVariant(true, true, "auto").exec_fast);
  EXPECT_TRUE(ChooseVariant(true, true, "auto").warning.empty());
}

TEST(ChooseVariantTest, GenericWhenTheCpuCannotOrTheSiblingIsMissing) {
  EXPECT_FALSE(ChooseVariant(false, true, nullptr).exec_fast);
  EXPECT_FALSE(ChooseVariant(true, false, nullptr).exec_fast);
  EXPECT_FALSE(ChooseVariant(false, false, "auto").exec_fast);
}

TEST(ChooseVariantTest, DvprArchGenericKeepsTheGenericCode) {
  const VariantChoice c = ChooseVariant(true, true, "generic");
  EXPECT_FALSE(c.exec_fast);
  EXPECT_TRUE(c.warning.empty());
}

TEST(ChooseVariantTest, AnUnknownValueIsWarnedAboutAndReadAsAuto) {
  const VariantChoice c = ChooseVariant(true, true, "avx512");
  EXPECT_TRUE(c.exec_fast);
  EXPECT_EQ(c.warning, "dvpr: DVPR_ARCH=avx512 is not generic or auto; reading it as auto");
}

TEST(CompiledArchTest, NamesTheTargetOfThisBuild) {
#if defined(__x86_64__) && defined(__AVX2__)
  EXPECT_EQ(CompiledArch(), "x86-64-v3");
#elif defined(__x86_64__)
  EXPECT_EQ(CompiledArch(), "x86-64");
#else
  EXPECT_FALSE(CompiledArch().empty());
#endif
}

#ifdef DVPR_DISPATCH_BUILD
// `dvpr --version` with `env` ("DVPR_ARCH=...") in its environment, started without a shell.
std::string Version(const std::string& env) {
  const std::filesystem::path out = std::filesystem::path(DVPR_TEST_TMP) / "dispatch_version.txt";
  testing_support::RunProgram({std::string(DVPR_BINARY_DIR) + "/dvpr", "--version"}, out, {}, {}, {env});
  return testing_support::Slurp(out);
}

TEST(DispatchTest, DvprRunsTheFastBuildWhereTheCpuCanAndTheGenericOneOnRequest) {
  const std::string fast = CpuRunsX86_64_V3() ? "x86-64-v3" : "x86-64";
  EXPECT_NE(Version("DVPR_ARCH=auto").find("(" + fast + ")"), std::string::npos);
  EXPECT_NE(Version("DVPR_ARCH=generic").find("(x86-64)"), std::string::npos);
}
#endif

}  // namespace
}  // namespace dvpr
