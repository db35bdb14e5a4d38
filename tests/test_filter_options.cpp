// The parameter table (the one definition every adapter reads) and the writing of results
// onto a mesh.
#include <gtest/gtest.h>

#include <set>

#include "filter/apply_results.h"
#include "test_support.h"

using namespace nvv_test;

TEST(FilterOptions, TableDefaultsAreTheCoreDefaults) {
  const nvv::FilterOptions o = nvv::DefaultOptions();
  const nvv::Params p;
  EXPECT_EQ(p.k, o.core.k);
  EXPECT_EQ(p.absoluteRadius, o.core.absoluteRadius);
  EXPECT_EQ(p.creaseAngleDeg, o.core.creaseAngleDeg);
  EXPECT_EQ(p.cornerAngleDeg, o.core.cornerAngleDeg);
  EXPECT_EQ(p.stopAtCreases, o.core.stopAtCreases);
  EXPECT_EQ(p.fit, o.core.fit);
  EXPECT_EQ(p.fitRounds, o.core.fitRounds);
  EXPECT_EQ(p.cubicFit, o.core.cubicFit);
  EXPECT_EQ(p.thinCreases, o.core.thinCreases);
  EXPECT_EQ(p.classRule, o.core.classRule);
  EXPECT_EQ(p.maxNeighbourhood, o.core.maxNeighbourhood);
  EXPECT_TRUE(nvv::ValidateOptions(o).empty());
}

TEST(FilterOptions, NamesAreUniqueAndEveryParameterIsSettable) {
  std::set<std::string> names;
  for (const auto& spec : nvv::FilterParameterTable()) {
    EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
    nvv::FilterOptions o;
    EXPECT_EQ("", nvv::SetOption(o, spec.name, spec.defaultValue)) << spec.name;
    EXPECT_EQ(spec.defaultValue, nvv::GetOption(o, spec.name)) << spec.name;
    const double other = spec.type == nvv::ParamType::Float ? (spec.minValue + spec.maxValue) / 2
                         : spec.type == nvv::ParamType::Int  ? spec.maxValue
                                                             : (spec.defaultValue == 0 ? 1 : 0);
    EXPECT_EQ("", nvv::SetOption(o, spec.name, other)) << spec.name;
    EXPECT_EQ(other, nvv::GetOption(o, spec.name)) << spec.name;  // SetOption and GetOption mirror each other
    if (spec.type == nvv::ParamType::Enum) {
      EXPECT_EQ(spec.choices.size(), spec.tokens.size()) << spec.name;
      EXPECT_NE("", nvv::SetOption(o, spec.name, double(spec.choices.size()))) << spec.name;
    }
    if (spec.type == nvv::ParamType::Float) {
      EXPECT_NE("", nvv::SetOption(o, spec.name, spec.maxValue * 2 + 1)) << spec.name;
    }
    EXPECT_NE("", nvv::SetOption(o, spec.name, std::nan(""))) << spec.name;
  }
  nvv::FilterOptions o;
  EXPECT_NE("", nvv::SetOption(o, "no_such_parameter", 1));
  // Found by the fuzzer: a boolean given a huge number reached an undefined double -> int
  // conversion. Booleans take 0 or 1 only.
  EXPECT_NE("", nvv::SetOption(o, "stop_at_creases", -1.55301e+34));
  EXPECT_NE("", nvv::SetOption(o, "update_normals", 2));
  EXPECT_TRUE(o.core.stopAtCreases && o.updateNormals);
}

// The dialog, --help and PyMeshLab offer the table's ranges; the core must accept every value in
// them (its ranges are the same constants, limits.h), and a value just outside is refused by the
// table with the range in the message.
TEST(FilterOptions, TheCoreAcceptsEveryValueTheTableOffers) {
  for (const auto& spec : nvv::FilterParameterTable()) {
    if (spec.type != nvv::ParamType::Float && spec.type != nvv::ParamType::Int) continue;
    const double step = spec.type == nvv::ParamType::Int ? 1.0 : 0.01;
    for (double v : {spec.minValue, spec.minValue + step, spec.maxValue - step, spec.maxValue}) {
      nvv::FilterOptions o = nvv::DefaultOptions();
      ASSERT_EQ("", nvv::SetOption(o, spec.name, v)) << spec.name << " = " << v;
      EXPECT_EQ("", nvv::ValidateOptions(o)) << spec.name << " = " << v;
    }
    nvv::FilterOptions o = nvv::DefaultOptions();
    const std::string below = nvv::SetOption(o, spec.name, spec.minValue - step);
    EXPECT_NE(std::string::npos, below.find("outside its range")) << spec.name << ": " << below;
  }
}

// Caps below what a uniform mesh holds within the radius still give a defined result.
TEST(FilterOptions, TinyNeighbourhoodCapsRunToTheEnd) {
  TMesh m;
  nvv_shapes::Cube(m, 5.0, 6);
  for (int cap : {1, 2, 4, 15}) {
    nvv::Params p = WithK(3);
    p.maxNeighbourhood = cap;
    const NvvRun r = RunNvv(m, p);
    ASSERT_TRUE(r.st.ok) << cap << ": " << r.st.message;
    EXPECT_EQ(r.res.size(), r.sum.capped) << cap;
    for (const auto& v : r.res) {
      EXPECT_TRUE(std::isfinite(v.normal[0]) && std::isfinite(v.k1) && std::isfinite(v.k2)) << cap;
      if (!v.Has(nvv::kNormalValid)) continue;
      EXPECT_NEAR(1.0, std::sqrt(v.normal[0] * v.normal[0] + v.normal[1] * v.normal[1] + v.normal[2] * v.normal[2]), 1e-5)
          << cap;
    }
  }
}

TEST(ApplyResults, WritesOrderedCurvatureClassesAndSelection) {
  TMesh m;
  nvv_shapes::Roof(m, 90.0);
  nvv::FilterOptions o = nvv::DefaultOptions();
  o.selection = nvv::SelectionMode::CreasesAndCorners;
  const NvvRun r = RunNvv(m, o.core);
  ASSERT_TRUE(r.st.ok);
  nvv::ApplyResults<TMesh>::Apply(m, r.res, o);
  auto cls = vcg::tri::Allocator<TMesh>::GetPerVertexAttribute<double>(m, nvv::AttributeNames::Class());
  int crease = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const auto& v = m.vert[i];
    EXPECT_GE(v.cK1(), v.cK2());
    EXPECT_EQ(double(int(r.res[i].cls)), cls[i]);
    EXPECT_EQ(r.res[i].cls == nvv::VertexClass::Crease || r.res[i].cls == nvv::VertexClass::Corner, v.IsS());
    EXPECT_EQ(nvv::ClassColor(r.res[i].cls), v.cC());
    crease += r.res[i].cls == nvv::VertexClass::Crease;
  }
  EXPECT_GT(crease, 20);
}

TEST(ApplyResults, QualityModesOnASphere) {
  TMesh m;
  nvv_shapes::PaperSphere(m, 31);
  const NvvRun r = RunNvv(m, nvv::Params());
  ASSERT_TRUE(r.st.ok);
  bool valid;
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    if (!Interior(m.vert[i].cP(), 10)) continue;
    EXPECT_NEAR(1.0 / 31, nvv::QualityValue(r.res[i], nvv::QualityMode::MeanCurvature, valid), 1e-3);
    EXPECT_NEAR(1.0 / (31 * 31), nvv::QualityValue(r.res[i], nvv::QualityMode::GaussianCurvature, valid), 1e-4);
    EXPECT_NEAR(1.0, nvv::QualityValue(r.res[i], nvv::QualityMode::ShapeIndex, valid), 0.05);  // a cap
  }
}
