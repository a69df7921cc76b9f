#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/toml_section.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

TEST(ClosestMatch, FindsNearMissesOnly) {
  EXPECT_EQ(closest_match("mass_kgg", {"mass_kg", "length_mm"}).value_or(""), "mass_kg");
  EXPECT_FALSE(closest_match("banana", {"mass_kg", "length_mm"}).has_value());
}

TEST(TomlSection, ErrorsNameFileLineAndKey) {
  testing::TempDir dir;
  const auto f = dir.write("a.toml", "x = 1\n[t]\ny = -2\nz = \"s\"\n");
  const toml::table doc = parse_toml_file(f);
  TomlSection root(doc, f);
  EXPECT_DOUBLE_EQ(root.positive("x"), 1.0);
  TomlSection t = root.section("t");
  try {
    t.positive("y");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(f.string() + ":3: key 't.y'"), std::string::npos) << m;
  }
  EXPECT_THROW(t.number("z"), InputError);
  EXPECT_THROW(t.number("w"), InputError);
  EXPECT_EQ(t.in_range("w", 0, 1, 0.5), 0.5);
  EXPECT_NO_THROW(t.finish());  // y, z and w were all asked for
}

TEST(TomlSection, FinishRejectsUnreadKeys) {
  testing::TempDir dir;
  const auto f = dir.write("a.toml", "speed_rpm = 1\nsped_rpm = 2\n");
  const toml::table doc = parse_toml_file(f);
  TomlSection root(doc, f);
  root.number("speed_rpm");
  try {
    root.finish();
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("unknown key 'sped_rpm'"), std::string::npos) << m;
    EXPECT_NE(m.find(":2:"), std::string::npos) << m;
  }
}

TEST(TomlSection, SyntaxErrorNamesLine) {
  testing::TempDir dir;
  const auto f = dir.write("bad.toml", "a = 1\nb = = 2\n");
  try {
    parse_toml_file(f);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml:2:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fourbar
