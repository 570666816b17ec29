// SPDX-License-Identifier: BSD-3-Clause
// Scene comparison shared by the scene tests (OBJ round trips, VTK conversion).
#ifndef mesolight_SceneTestUtilities_h
#define mesolight_SceneTestUtilities_h

#include "TriangleScene.h"

#include <gtest/gtest.h>

#include <cstddef>

namespace mesolight
{
namespace vlftest
{

/** Expects a and b to be the same scene, bit for bit (positions, triangles, materials). */
inline void ExpectSameScene(const TriangleScene& a, const TriangleScene& b)
{
  ASSERT_EQ(a.Positions.size(), b.Positions.size());
  ASSERT_EQ(a.Triangles, b.Triangles);
  ASSERT_EQ(a.MaterialIds, b.MaterialIds);
  for (std::size_t v = 0; v < a.Positions.size(); ++v)
  {
    ASSERT_EQ(a.Positions[v], b.Positions[v]) << "vertex " << v; // bit-exact: 9 digits
  }
  ASSERT_EQ(a.Materials.size(), b.Materials.size());
  for (std::size_t m = 0; m < a.Materials.size(); ++m)
  {
    EXPECT_EQ(a.Materials[m].Name, b.Materials[m].Name);
    EXPECT_EQ(a.Materials[m].Diffuse, b.Materials[m].Diffuse);
    EXPECT_EQ(a.Materials[m].Specular, b.Materials[m].Specular);
    EXPECT_EQ(a.Materials[m].Emission, b.Materials[m].Emission);
  }
}

} // namespace vlftest
} // namespace mesolight

#endif
