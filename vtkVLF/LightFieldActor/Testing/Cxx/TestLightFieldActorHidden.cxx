// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor::AddHiddenSurface: a surface left out of the drawing in every mode (a relief
// actor draws it instead, `vlf view --relief`), nothing else changed. Which pixels show the
// surface comes from an exact ray cast of the same camera (Embree on the field's scene).
#include "WalkthroughTestViewer.h"

#include "MessageCapture.h"

#include <algorithm>

namespace mesolight
{
namespace walkthroughtest
{
namespace
{

TEST(Walkthrough, HiddenSurfaceIsLeftOutInEveryModeAndNothingElse)
{
  const vlf::LightField& field = PlainCornellField(129);
  const std::vector<std::size_t> back = SurfaceTriangles(field.Scene(), "back");
  // 1: the back wall is the first hit, 2: something else is, 0: nothing.
  const EmbreeScene embree(field.Scene());
  const vlf::ViewFrame view = CornellView(field);
  std::vector<int> label(static_cast<std::size_t>(Size) * Size, 0);
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      const SceneHit hit = embree.Intersect(view.Ray(i + 0.5f, j + 0.5f));
      if (hit.Hit())
      {
        label[static_cast<std::size_t>(j) * Size + i] =
          std::find(back.begin(), back.end(), hit.Triangle) != back.end() ? 1 : 2;
      }
    }
  }
  // Pixels whose 3 x 3 neighbourhood is all one label (the edges may go either way).
  const auto uniform = [&](int i, int j, int which)
  {
    for (int dj = -1; dj <= 1; ++dj)
    {
      for (int di = -1; di <= 1; ++di)
      {
        const int x = std::clamp(i + di, 0, Size - 1), y = std::clamp(j + dj, 0, Size - 1);
        if (label[static_cast<std::size_t>(y) * Size + x] != which)
        {
          return false;
        }
      }
    }
    return true;
  };
  Viewer viewer(field);
  vtkNew<mesolight_test::MessageCapture> notes; // "no mirror surfaces"
  notes->Watch(viewer.Actor);
  for (int mode = vtkLightFieldActor::Geometry; mode <= vtkLightFieldActor::Coherent; ++mode)
  {
    SCOPED_TRACE(vtkLightFieldActor::GetRenderModeAsString(mode));
    const Images all = viewer.Render(mode);
    viewer.Actor->AddHiddenSurface("back");
    const Images hidden = viewer.Render(mode);
    int wall = 0, wallBlack = 0, other = 0, otherSame = 0;
    for (int j = 0; j < Size; ++j)
    {
      for (int i = 0; i < Size; ++i)
      {
        const std::size_t p = static_cast<std::size_t>(j) * Size + i;
        const float shown =
          std::max(all.Display[p].x, std::max(all.Display[p].y, all.Display[p].z));
        const glm::vec3 d = glm::abs(hidden.Display[p] - all.Display[p]);
        if (uniform(i, j, 1) && shown > 0.0f)
        {
          ++wall;
          wallBlack += glm::length(hidden.Display[p]) == 0.0f ? 1 : 0;
        }
        else if (uniform(i, j, 2))
        {
          ++other;
          otherSame += std::max(d.x, std::max(d.y, d.z)) <= 1.0f / 255.0f ? 1 : 0;
        }
      }
    }
    EXPECT_GT(wall, Size * Size / 20);
    EXPECT_EQ(wallBlack, wall); // the background shows through
    EXPECT_EQ(otherSame, other);
    viewer.Actor->RemoveAllHiddenSurfaces();
    const Images again = viewer.Render(mode);
    EXPECT_EQ(again.Display, all.Display);
  }
  EXPECT_TRUE(notes->Errors.empty()) << notes->AllErrors();
}

TEST(Walkthrough, UnknownHiddenSurfaceIsReportedWithTheNames)
{
  Viewer viewer(PlainCornellField(129));
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(viewer.Actor);
  viewer.Actor->AddHiddenSurface("wall");
  EXPECT_TRUE(messages->HasError("floor, ceiling, back, left, right, light, short, tall"))
    << messages->AllErrors();
  const Images images = viewer.Render(vtkLightFieldActor::Progressive);
  EXPECT_EQ(messages->Errors.size(), 1u); // once
}

} // namespace
} // namespace walkthroughtest
} // namespace mesolight
