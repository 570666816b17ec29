// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor beside other actors (offscreen; run under Xvfb): occlusion of mirror pixels,
// ordinary actors and relief surfaces composed in every mode, the field from the filter and the
// composite mapper, viewports, and bad input.
#include "MessageCapture.h"
#include "WalkthroughTestViewer.h"
#include "vtkVirtualLightFieldCore.h"

namespace mesolight
{
namespace
{
using namespace walkthroughtest;

TEST(Walkthrough, DiffuseBoxInFrontOfMirrorHidesExactlyItsPixels)
{
  const vlf::LightField& field = MirrorCornellField(513);
  // Ray-cast masks: visible mirror pixels, and mirror pixels a block hides (the mirror alone
  // would be hit there).
  TriangleScene mirrorOnly;
  mirrorOnly.Materials = field.Scene().Materials;
  for (std::size_t t = 0; t < field.Scene().TriangleCount(); ++t)
  {
    if (glm::length(field.Scene().MaterialOf(t).Specular) > 0.0f)
    {
      mirrorOnly.Positions.push_back(field.Scene().Vertex(t, 0));
      mirrorOnly.Positions.push_back(field.Scene().Vertex(t, 1));
      mirrorOnly.Positions.push_back(field.Scene().Vertex(t, 2));
      const auto n = static_cast<std::uint32_t>(mirrorOnly.Positions.size());
      mirrorOnly.Triangles.emplace_back(n - 3, n - 2, n - 1);
      mirrorOnly.MaterialIds.push_back(field.Scene().MaterialIds[t]);
    }
  }
  const EmbreeScene mirrorScene(mirrorOnly);
  Viewer viewer(field);
  const vlf::ViewFrame view = viewer.SetCamera(
    field, glm::vec3(60.0f, 220.0f, 330.0f), glm::vec3(550.0f, 150.0f, 350.0f), 60.0f);
  const vlf::WalkthroughTracer walk(field);
  const std::vector<vlf::PixelClass> classes = walk.ClassifyView(view);
  // Mirror pixels reflecting the box's open front stay black either way: count the lit ones.
  std::vector<float> traced(static_cast<std::size_t>(Size) * Size * 4);
  walk.ShadeRows(view, vlf::PixelRect{ 0, 0, Size, Size }, false, vlf::SpecularQuality::Traced,
    vlf::TraceOptions{}, 0, Size, traced.data());
  std::vector<std::uint8_t> lit(classes.size(), 0);
  std::size_t visible = 0, hidden = 0, litCount = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * Size + x;
      const bool mirror = classes[i] == vlf::PixelClass::Mirror;
      const glm::vec3 display =
        vlf::ToneMap(glm::vec3(traced[4 * i], traced[4 * i + 1], traced[4 * i + 2]), Exposure,
          vlf::ToneMapOperator::Clamp);
      lit[i] =
        mirror && std::max(display.x, std::max(display.y, display.z)) * 255.0f > 0.5f ? 1 : 0;
      litCount += lit[i];
      visible += mirror ? 1 : 0;
      hidden += !mirror && mirrorScene.Intersect(view.Ray(x + 0.5f, y + 0.5f)).Hit() ? 1 : 0;
    }
  }
  for (const int mode : { vtkLightFieldActor::Coherent, vtkLightFieldActor::Progressive })
  {
    viewer.Actor->SetRenderMode(mode);
    viewer.Window->Render();
    viewer.Actor->WaitForTracedReflections(60.0);
    const Images full = viewer.Render(mode);
    Dump(std::string("hides-") + vtkLightFieldActor::GetRenderModeAsString(mode), full.Radiance);
    vtkLightFieldActorTesting::SetReflectionBouncesShort(viewer.Actor, 1);
    viewer.Window->Render();
    viewer.Actor->WaitForTracedReflections(60.0);
    const Images cut = viewer.Render(mode);
    vtkLightFieldActorTesting::SetReflectionBouncesShort(viewer.Actor, 0);
    std::size_t drawn = 0, both = 0, drawnOffMirror = 0;
    for (std::size_t i = 0; i < classes.size(); ++i)
    {
      const bool mirrorDrawn = full.Display[i] != cut.Display[i];
      drawn += mirrorDrawn ? 1 : 0;
      both += mirrorDrawn && lit[i] ? 1 : 0;
      drawnOffMirror += mirrorDrawn && classes[i] != vlf::PixelClass::Mirror ? 1 : 0;
    }
    std::cout << vtkLightFieldActor::GetRenderModeAsString(mode) << ": lit mirror pixels drawn "
              << drawn << ", ray cast " << litCount << " (" << both << " in both; " << visible
              << " visible mirror pixels in all), " << drawnOffMirror << " drawn off the mirror; "
              << hidden << " mirror pixels hidden by the block\n";
    EXPECT_GT(hidden, 100u);
    EXPECT_EQ(drawnOffMirror, 0u);
    // Pixels within a display level of black may round either way.
    EXPECT_LE(litCount - both, litCount / 100 + 2);
    EXPECT_LE(drawn - both, litCount / 100 + 2);
  }
}

// An ordinary actor (an unlit sphere) and a relief surface (vtkReliefMapper, flat relief at
// depth 0 so its true surface is its quad) inside the box: the sphere partly hidden by the tall
// block, both partly in front of the mirror wall, the sphere partly in front of the relief. In
// every mode the pixels each shows are exactly those a ray cast of the field's scene plus the
// analytic sphere and the quad gives it.
TEST(Walkthrough, OrdinaryActorAndReliefSurfaceOccludeCorrectlyInEveryMode)
{
  const vlf::LightField& field = MirrorCornellField(513);
  Viewer viewer(field);
  const glm::vec3 centre(490.0f, 110.0f, 420.0f);
  const float radius = 75.0f;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre.x, centre.y, centre.z);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(256);
  sphere->SetPhiResolution(256);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ball;
  ball->SetMapper(mapper);
  ball->GetProperty()->SetColor(1.0, 0.0, 1.0);
  ball->GetProperty()->LightingOff();
  viewer.Renderer->AddActor(ball);

  // The relief: a quad parallel to the mirror wall, 10 mm in front of it, through the sphere.
  const glm::vec3 origin(540.0f, 30.0f, 150.0f), edgeZ(0.0f, 0.0f, 300.0f),
    edgeY(0.0f, 200.0f, 0.0f);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(origin.x, origin.y, origin.z);
  plane->SetPoint1(origin.x + edgeZ.x, origin.y + edgeZ.y, origin.z + edgeZ.z);
  plane->SetPoint2(origin.x + edgeY.x, origin.y + edgeY.y, origin.z + edgeY.z);
  vtkNew<vtkProceduralReliefSource> depth;
  depth->SetPatternToFlat();
  depth->SetFlatDepth(0.0);
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputConnection(depth->GetOutputPort());
  vtkNew<vtkReliefMapper> reliefMapper;
  reliefMapper->SetInputConnection(plane->GetOutputPort());
  reliefMapper->SetReliefTextureConnection(relief->GetOutputPort());
  vtkNew<vtkActor> wall;
  wall->SetMapper(reliefMapper);
  // Ambient only: the relief's VTK-compatible lighting then gives exactly this colour.
  wall->GetProperty()->SetAmbientColor(0.0, 1.0, 1.0);
  wall->GetProperty()->SetAmbient(1.0);
  wall->GetProperty()->SetDiffuse(0.0);
  wall->GetProperty()->SetSpecular(0.0);
  viewer.Renderer->AddActor(wall);
  viewer.Renderer->ResetCameraClippingRange();

  // The ray-cast masks: the field's scene, the analytic sphere and the quad (unit coordinates).
  TriangleScene scene = field.Scene();
  SceneMaterial quadMaterial;
  quadMaterial.Name = "relief";
  const std::uint32_t quadId = scene.AddMaterial(quadMaterial);
  const std::size_t quadFirst = scene.TriangleCount();
  scene.AddPolygon(
    { vlf::ToUnit(field, origin), vlf::ToUnit(field, origin + edgeZ),
      vlf::ToUnit(field, origin + edgeZ + edgeY), vlf::ToUnit(field, origin + edgeY) },
    quadId);
  SceneSphere unitSphere;
  unitSphere.Center = vlf::ToUnit(field, centre);
  unitSphere.Radius = radius * field.NormalizationScale();
  const EmbreeScene everything(scene, { unitSphere });
  const EmbreeScene withoutSphere(scene);
  const vlf::ViewFrame view = CornellView(field);
  const vlf::WalkthroughTracer walk(field);
  const std::vector<vlf::PixelClass> classes = walk.ClassifyView(view);
  std::vector<std::uint8_t> expected(
    static_cast<std::size_t>(Size) * Size, 0); // 1 sphere, 2 relief
  std::size_t sphereVisible = 0, sphereHidden = 0, reliefVisible = 0, overMirror = 0,
              sphereOverRelief = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const SceneRay ray = view.Ray(x + 0.5f, y + 0.5f);
      const SceneHit hit = everything.Intersect(ray);
      const std::size_t i = static_cast<std::size_t>(y) * Size + x;
      const glm::vec3 oc = ray.Origin - unitSphere.Center;
      const float b = glm::dot(oc, ray.Direction);
      const bool onSphere =
        b * b - (glm::dot(oc, oc) - unitSphere.Radius * unitSphere.Radius) > 0.0f;
      const SceneHit behind = withoutSphere.Intersect(ray);
      const bool reliefBehind = behind.Triangle != SceneHit::None && behind.Triangle >= quadFirst;
      if (hit.Sphere != SceneHit::None)
      {
        expected[i] = 1;
        ++sphereVisible;
        sphereOverRelief += reliefBehind ? 1 : 0;
      }
      else if (hit.Triangle != SceneHit::None && hit.Triangle >= quadFirst)
      {
        expected[i] = 2;
        ++reliefVisible;
      }
      else if (onSphere)
      {
        ++sphereHidden;
      }
      overMirror += expected[i] != 0 && classes[i] == vlf::PixelClass::Mirror ? 1 : 0;
    }
  }
  std::cout << "sphere: " << sphereVisible << " visible pixels (" << sphereOverRelief
            << " in front of the relief), " << sphereHidden
            << " hidden by the box; relief: " << reliefVisible << " visible; " << overMirror
            << " of them in front of the mirror\n";
  ASSERT_GT(sphereVisible, 100u);
  ASSERT_GT(sphereHidden, 50u);
  ASSERT_GT(reliefVisible, 100u);
  ASSERT_GT(sphereOverRelief, 20u);
  ASSERT_GT(overMirror, 100u);
  for (int mode = vtkLightFieldActor::Geometry; mode <= vtkLightFieldActor::Coherent; ++mode)
  {
    const Images images = viewer.Render(mode);
    std::size_t agree = 0, wrong = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
      const glm::vec3 d = images.Display[i];
      const bool magenta = d.x > 0.99f && d.y < 0.01f && d.z > 0.99f;
      const bool cyan = d.x < 0.01f && d.y > 0.99f && d.z > 0.99f;
      const std::uint8_t seen = magenta ? 1 : (cyan ? 2 : 0);
      agree += seen == expected[i] && seen != 0 ? 1 : 0;
      wrong += seen != expected[i] ? 1 : 0;
    }
    // Depth: the z-buffer's eye distance against the ray cast's (scene, sphere and quad alike).
    vtkNew<vtkFloatArray> z;
    viewer.Window->GetZbufferData(0, 0, Size - 1, Size - 1, z);
    double clip[2];
    viewer.Renderer->GetActiveCamera()->GetClippingRange(clip);
    double worstDepth = 0.0;
    std::size_t depthPixels = 0;
    for (int y = 0; y < Size; ++y)
    {
      for (int x = 0; x < Size; ++x)
      {
        const SceneRay ray = view.Ray(x + 0.5f, y + 0.5f);
        const SceneHit hit = everything.Intersect(ray);
        if (!hit.Hit())
        {
          continue;
        }
        const std::size_t i = static_cast<std::size_t>(y) * Size + x;
        const double ndc = 2.0 * z->GetValue(static_cast<vtkIdType>(i)) - 1.0;
        const double eye =
          2.0 * clip[0] * clip[1] / (clip[1] + clip[0] - ndc * (clip[1] - clip[0]));
        const double cast =
          hit.T * glm::dot(ray.Direction, view.Forward) / field.NormalizationScale();
        worstDepth = std::max(worstDepth, std::abs(eye - cast) / cast);
        ++depthPixels;
      }
    }
    std::cout << "sphere and relief masks, " << vtkLightFieldActor::GetRenderModeAsString(mode)
              << ": " << agree << " pixels agree, " << wrong << " differ; depth of " << depthPixels
              << " pixels vs the ray cast: worst relative difference " << worstDepth << "\n";
    // The relief's level of detail (on by default) refines far hits only to an eighth of the
    // pixel footprint: measured 6.0e-4 (the bound was 5e-4 with it off).
    EXPECT_LT(worstDepth, 1e-3);
    // Tessellated vs analytic silhouette and pixel-centre sampling: a thin outline at most.
    EXPECT_LE(wrong, (sphereVisible + reliefVisible) / 50 + 8);
  }
}

// The field straight from a vtkVirtualLightField that nobody updated: the actor updates it at
// render time and shows it (the same pixels as the same field set directly).
TEST(Walkthrough, FieldFromTheVirtualLightFieldFilter)
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> filter;
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetDirections(513);
  filter->SetRaysPerSide(16);
  filter->SetIterations(2);
  const vlf::LightField& any = MirrorCornellField(513);
  Viewer viewer(any);
  viewer.Actor->SetLightFieldFilter(filter);
  const Images fromFilter = viewer.Render(vtkLightFieldActor::Progressive);
  ASSERT_NE(vtkLightFieldActorCore::GetLightField(viewer.Actor), nullptr);
  EXPECT_EQ(vtkLightFieldActorCore::GetLightField(viewer.Actor),
    vtkVirtualLightFieldCore::GetLightField(filter));
  std::size_t lit = 0;
  for (const glm::vec3& d : fromFilter.Display)
  {
    lit += d.x + d.y + d.z > 0.05f ? 1 : 0;
  }
  std::cout << "field from the filter: " << lit << " of " << fromFilter.Display.size()
            << " pixels lit\n";
  EXPECT_GT(lit, fromFilter.Display.size() * 3 / 4);
  vtkLightFieldActorCore::SetLightField(
    viewer.Actor, vtkVirtualLightFieldCore::GetLightField(filter));
  const Images direct = viewer.Render(vtkLightFieldActor::Progressive);
  EXPECT_EQ(direct.Display, fromFilter.Display);

  // The mirror box through the filter; the filter changes while the worker traces the mirror:
  // the actor stops the worker before the filter frees the field, then traces the new one.
  vtkNew<vtkTriangleSceneConverter> converter;
  filter->SetInputData(converter->ToPolyData(MakeCornellBoxWithMirror()));
  viewer.Actor->SetLightFieldFilter(filter);
  viewer.Render(vtkLightFieldActor::Progressive);
  viewer.Render(vtkLightFieldActor::Progressive); // the same view: the worker starts
  filter->SetIterations(3);
  viewer.Render(vtkLightFieldActor::Progressive);
  // (The new field may reuse the old one's address: the actor must notice all the same.)
  EXPECT_EQ(vtkLightFieldActorCore::GetLightField(viewer.Actor)->IterationsDone, 3);
  EXPECT_TRUE(viewer.Actor->HasMirrors());
  ASSERT_TRUE(viewer.Actor->WaitForTracedReflections(60.0));
  viewer.Render(vtkLightFieldActor::Progressive);
  EXPECT_TRUE(viewer.Actor->GetLastFrameConverged());
}

#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 0)
// vtkCompositeLightFieldMapper (ParaView's Light Field representation) draws the filter's
// output, which carries its atlas as field data, exactly as the actor's progressive mode draws
// the diffuse Cornell box: same shader, same atlas. Also as a block of a multiblock (what
// ParaView hands it). Must fail: another exposure.
TEST(Walkthrough, CompositeMapperDrawsTheFilterOutputAsTheActor)
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> filter;
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetDirections(513);
  filter->SetRaysPerSide(16);
  filter->SetIterations(2);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  Viewer viewer(*vtkVirtualLightFieldCore::GetLightField(filter));
  const Images expected = viewer.Render(vtkLightFieldActor::Progressive);

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(1);
  blocks->SetBlock(0, filter->GetOutput());
  for (const bool composite : { false, true })
  {
    vtkNew<vtkCompositeLightFieldMapper> mapper;
    if (composite)
    {
      mapper->SetInputDataObject(blocks);
    }
    else
    {
      mapper->SetInputConnection(filter->GetOutputPort());
    }
    mapper->SetToneMap(vtkCompositeLightFieldMapper::Clamp);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    viewer.Renderer->RemoveActor(viewer.Actor);
    viewer.Renderer->AddActor(actor);
    const auto differing = [&](double exposure)
    {
      mapper->SetExposure(exposure);
      viewer.Window->Render();
      const Images got = viewer.Grab();
      std::size_t differ = 0;
      for (std::size_t i = 0; i < expected.Display.size(); ++i)
      {
        const glm::vec3 d = glm::abs(got.Display[i] - expected.Display[i]) * 255.0f;
        differ += std::max(d.x, std::max(d.y, d.z)) > 1.5f ? 1 : 0;
      }
      return differ;
    };
    const std::size_t same = differing(Exposure);
    const std::size_t other = differing(2.0 * Exposure);
    std::cout << (composite ? "multiblock" : "polydata") << ": " << same << " of "
              << expected.Display.size() << " pixels differ by more than 1 level from the "
              << "actor's progressive image; at twice the exposure " << other << "\n";
    EXPECT_LE(same, expected.Display.size() / 200);
    EXPECT_GT(other, expected.Display.size() / 2);
    viewer.Renderer->RemoveActor(actor);
    viewer.Renderer->AddActor(viewer.Actor);
  }
}
#endif

// A renderer in the right half of a window (its viewport does not start at the window's
// origin): the screen-space values land on the same pixels as in a window of its own.
TEST(Walkthrough, ViewportOffsetInTheWindow)
{
  const vlf::LightField& field = MirrorCornellField(513);
  Viewer alone(field);
  Viewer half(field);
  half.Window->SetSize(2 * Size, Size);
  half.Renderer->SetViewport(0.5, 0.0, 1.0, 1.0);
  for (const int mode : { vtkLightFieldActor::Raytrace, vtkLightFieldActor::Coherent })
  {
    const Images expected = alone.Render(mode);
    half.Actor->SetRenderMode(mode);
    half.Window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    half.Window->GetPixelData(Size, 0, 2 * Size - 1, Size - 1, 1, pixels);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < expected.Display.size(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        const int got = pixels->GetValue(3 * static_cast<vtkIdType>(i) + c);
        const int want = static_cast<int>(std::lround(255.0f * expected.Display[i][c]));
        differ += got != want ? 1 : 0;
      }
    }
    std::cout << vtkLightFieldActor::GetRenderModeAsString(mode) << " in the right half: " << differ
              << " channel values differ\n";
    EXPECT_EQ(differ, 0u);
  }
}

// A copy of a snapshot claiming another format version, with a valid header checksum (the
// header's 64-bit multiply-xorshift hash of vtkVLF/LightField/core/Snapshot.cxx, over its first 40
// bytes).
void WriteOtherVersion(const std::string& from, const std::string& to, std::uint32_t version)
{
  std::ifstream in(from, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 48u);
  std::memcpy(&bytes[8], &version, 4);
  std::uint64_t state = 0x243F6A8885A308D3ULL;
  for (int q = 0; q < 40; q += 8)
  {
    std::uint64_t word;
    std::memcpy(&word, &bytes[static_cast<std::size_t>(q)], 8);
    state = (state ^ word) * 0x9E3779B97F4A7C15ULL;
    state ^= state >> 29;
  }
  std::uint64_t h = state ^ (40ULL * 0xff51afd7ed558ccdULL);
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  std::memcpy(&bytes[40], &h, 8);
  std::ofstream out(to, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Bad input: clear messages, never a crash.
TEST(Walkthrough, BadInputIsReportedNotCrashed)
{
  vtkNew<vtkLightFieldActor> actor;
  vtkNew<mesolight_test::MessageCapture> log;
  log->Watch(actor);
  // Missing, foreign and truncated field files.
  EXPECT_FALSE(actor->LoadLightField("/nonexistent/field.vlf"));
  std::cout << "missing file: " << log->AllErrors();
  EXPECT_TRUE(log->HasError("field.vlf")) << log->AllErrors();
  log->Clear();
  const std::string dir = MESOLIGHT_TEST_TEMP_DIR;
  {
    std::ofstream foreign(dir + "/foreign.vlf");
    foreign << "v 0 0 0\nf 1 2 3\n";
  }
  EXPECT_FALSE(actor->LoadLightField(dir + "/foreign.vlf"));
  std::cout << "foreign file: " << log->AllErrors();
  EXPECT_TRUE(log->HasError("not a Mesolight light field snapshot")) << log->AllErrors();
  log->Clear();
  vlf::WriteSnapshot(walkthroughtest::DiffuseCornellField(), dir + "/diffuse.vlf");
  {
    std::ifstream in(dir + "/diffuse.vlf", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(dir + "/truncated.vlf", std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  }
  EXPECT_FALSE(actor->LoadLightField(dir + "/truncated.vlf"));
  std::cout << "truncated file: " << log->AllErrors();
  EXPECT_TRUE(log->HasError("truncated")) << log->AllErrors();
  log->Clear();
  WriteOtherVersion(dir + "/diffuse.vlf", dir + "/version99.vlf", 99);
  EXPECT_FALSE(actor->LoadLightField(dir + "/version99.vlf"));
  std::cout << "other version: " << log->AllErrors();
  EXPECT_TRUE(log->HasError("snapshot version 99")) << log->AllErrors();

  // A renderer with the actor but no field, and a zero-size viewport: nothing drawn, no crash.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(32, 32);
  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(0.0, 0.0, 0.0, 0.0);
  window->AddRenderer(renderer);
  renderer->AddActor(actor);
  window->Render();
  vtkLightFieldActorCore::SetLightField(actor, &MirrorCornellField(513));
  for (int mode = vtkLightFieldActor::Geometry; mode <= vtkLightFieldActor::Coherent; ++mode)
  {
    actor->SetRenderMode(mode);
    window->Render();
    EXPECT_TRUE(actor->WaitForTracedReflections(10.0));
  }
  // A field without mirrors in the default mode: its diffuse textures, no word; in a mode
  // picked for mirrors: a warning, the diffuse textures.
  renderer->SetViewport(0.0, 0.0, 1.0, 1.0);
  log->Clear();
  EXPECT_TRUE(actor->LoadLightField(dir + "/diffuse.vlf"));
  actor->SetRenderModeToProgressive();
  window->Render();
  EXPECT_FALSE(log->HasWarning("no mirror surfaces")) << log->AllWarnings();
  actor->SetRenderModeToCoherent();
  window->Render();
  std::cout << "no mirrors: " << log->AllWarnings();
  EXPECT_TRUE(log->HasWarning("no mirror surfaces")) << log->AllWarnings();
  // Camera inside the tall block: back faces everywhere (a warning, black pixels).
  log->Clear();
  vtkLightFieldActorCore::SetLightField(actor, &MirrorCornellField(513));
  renderer->GetActiveCamera()->SetPosition(370.0, 150.0, 350.0);
  renderer->GetActiveCamera()->SetFocalPoint(370.0, 150.0, 600.0);
  renderer->ResetCameraClippingRange();
  actor->SetRenderModeToRaytrace();
  window->Render();
  std::cout << "camera in a wall: " << log->AllWarnings();
  EXPECT_TRUE(log->HasWarning("inside a wall")) << log->AllWarnings();
}

} // namespace
} // namespace mesolight
