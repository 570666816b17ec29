// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench relief`: accuracy and speed of every relief method, measured per map, view
// angle and step setting against exact references:
//  - hit error (texels) and silhouettes against the CPU reference (ReliefReference.h),
//  - shadows (first light) against the CPU reference's visibility,
//  - colour against the dense displaced mesh drawn by VTK's stock mapper (self-shadowing off).
// Prints a table, writes CSV and one chart per view angle (ms/frame vs mean hit error, Pareto
// front), and ends with a summary.
#ifndef mesolight_ReliefSweep_h
#define mesolight_ReliefSweep_h

#include <ostream>
#include <string>
#include <vector>

namespace mesolight
{

struct ReliefSweepSettings
{
  // Procedural pattern names, or "file": one map per entry of DepthFiles (without any, the Stone
  // pattern is written to a 16-bit PNG in the output directory and read back, which tests the
  // file path, not real data).
  std::vector<std::string> Maps{ "Bricks", "Stone", "HemisphereTorus", "file" };
  std::vector<std::string> DepthFiles;
  bool DepthFilesAreHeight = false; // the files store height (white = high), as game textures do
  bool NormalizeDepthFiles = false; // stretch each file's range to [0, 1] (DEMs in metres)
  bool UseNoDataValue = false;      // the files' texels holding NoDataValue have no data
  double NoDataValue = 0.0;
  bool UseFileNoDataValue = true; // else the value a GeoTIFF names (GDAL_NODATA) is data too
  std::vector<double> Angles{ 0.0, 45.0, 70.0, 80.0, 85.0 };
  int Width = 512;
  int Height = 512;
  int Frames = 5; // timed frames per configuration, after one warm-up frame
  // vtkReliefMapper method names, and "default": the settings of an untouched vtkReliefProperty
  // (what the mapper, the ParaView representation and `mesolight render` use). Empty: all.
  std::vector<std::string> Methods;
  std::string CsvFile;
  std::string PlotDirectory; // one PNG chart per view angle; empty: no charts
  int Resolution = 512;      // texels per side of the procedural maps
  double DepthScale = 0.04;
  // Frame each view so the wall fills the window (ReliefSceneOptions::FillViewport): frame times
  // then measure the march over the whole window at every angle, not a strip of it.
  bool FillViewport = true;
  // Step settings ("L+R") replacing the table for the methods with a linear or cone search
  // (linear search, POM, relief, interval, cone methods); empty: the table.
  std::vector<std::string> Steps;
  // Iteration budgets for max-mipmap instead of the built-in table (empty: 32, 64, 128).
  std::vector<int> Iterations;
  // How the relief is uploaded, each measured in the same run: "compact" (the default storage)
  // and "float" (vtkReliefProperty::FloatTextures, the float RGBA layout).
  std::vector<std::string> TextureStorages{ "compact" };
  // Draw the dense displaced mesh for the colour columns. Off for maps too large to mesh (its
  // size in MB is computed either way).
  bool DenseMesh = true;
  // Draw with level of detail (vtkReliefProperty's default; the sweep draws without it):
  // measures what it uploads (the GPU MB column).
  bool LevelOfDetail = false;
  // With LevelOfDetail: the most view rays per far pixel (vtkReliefProperty::FarViewRays); 0:
  // the property's default.
  int FarViewRays = 0;
};

/** One step setting of a method: what the mapper's LinearSteps / RefinementSteps mean for it. */
struct ReliefSweepStep
{
  int LinearSteps = 10;
  int RefinementSteps = 0;
  std::string Label; // e.g. "16+4", "iter 4", "-"
};

/** The step settings swept for a vtkReliefMapper method (see ReliefSweep.cxx for the table). */
std::vector<ReliefSweepStep> ReliefSweepStepsFor(int method);

/** A per-pixel count's mean over the covered pixels and its lock-step mean (8 x 4 groups). */
struct ExactTraversalCounts
{
  double Mean = 0.0;
  double LockStep = 0.0;
};

/** One measured configuration (map x view angle x method x step setting). */
struct ReliefSweepRow
{
  std::string Map;
  double Angle = 0.0;
  int Method = 0;
  std::string MethodName;
  // The row of the untouched defaults (method "default"): Method and Step are the default's.
  bool IsDefault = false;
  ReliefSweepStep Step;
  double MedianMs = 0.0;
  double FirstMs = 0.0; // the warm-up frame (shader compilation, uploads)
  // Relief-texture samples per covered pixel (SampleCountOutput): the march's fetches on any GPU,
  // free of llvmpipe's timing noise and fixed per-frame cost.
  double SamplesPerPixel = 0.0;
  // The same counts in lock step (MeanLockStepSampleCount, 8 x 4 pixel groups: a 32-lane warp):
  // what the march's loop arithmetic costs on SIMD hardware, where a group iterates until its
  // slowest pixel ends.
  double LockStepSamplesPerPixel = 0.0;
  // What exact traversals of per-cell depth bounds (maximum mipmaps, quadtree displacement
  // mapping) must fetch on this map and angle (the same in all its rows), per covered pixel and
  // in the same lock step: the floor (ReliefReference::BoundReachingCells, the cells whose bound
  // the exact ray reaches; no navigation), and an oracle told the right level at every step
  // (BoundTraversalOracle) over the pyramid levels the compact storage keeps and over all.
  ExactTraversalCounts Floor;
  ExactTraversalCounts OracleStoredLevels;
  ExactTraversalCounts OracleAllLevels;
  double HitMeanTexels = 0.0;
  double HitP99Texels = 0.0;
  double SilhouetteMismatch = 0.0; // % of the footprint
  double ColorRmse = 0.0;          // 8-bit levels, shaded (no self-shadowing) vs the dense mesh
  double Psnr = 0.0;
  double ShadowMismatch = 0.0; // % of pixels covered in both
  long long CoveredBoth = 0;
  long long Footprint = 0;
  bool FloatTextures = false; // uploaded as float RGBA (vtkReliefProperty::FloatTextures)
  double GpuMegaBytes = 0.0;  // the relief's textures on the GPU (vtkReliefMapper)
  // The dense displaced mesh of the same map as VTK's stock mapper uploads it: 32 bytes per
  // vertex (position, normal, texture coordinate) and 12 per triangle.
  double DenseMegaBytes = 0.0;
};

/**
 * Runs the sweep described by settings, printing progress, the table and the summary to out.
 * False (with a message on out) when a scene, a reference or an output file fails.
 */
bool RunReliefSweep(const ReliefSweepSettings& settings, std::ostream& out,
  std::vector<ReliefSweepRow>* rows = nullptr);

/**
 * `mesolight bench relief [options]`: args are the options after "relief". Returns the process
 * exit code: 0 success (or --help), 1 a failed run, 2 bad arguments.
 */
int RunReliefSweep(const std::vector<std::string>& args);

} // namespace mesolight

#endif
