// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkProceduralReliefSource
 * @brief   procedural depth map and albedo for relief-mapping tests and demos
 *
 * vtkProceduralReliefSource produces two images of Resolution[0] x Resolution[1] texels:
 * - output port 0: the depth map, float, 1 component, point scalars named "Depth", values
 *   in [0,1] (0 = top surface, 1 = deepest);
 * - output port 1: the albedo, unsigned char RGB, point scalars named "Albedo".
 *
 * Patterns (see core/ProceduralHeightFields.h): Bricks (running bond, deep mortar),
 * Stone (fractal noise), HemisphereTorus (the relief thesis test pattern, fig. 45: flat base
 * at depth 0.9, bumps rising to depth 0), Flat (FlatDepth everywhere) and SineWave
 * (d = 0.5 + 0.5 sin(2 pi fx u) cos(2 pi fy v)). Patterns are sampled at texel centres, so
 * their shape does not depend on the resolution, and are deterministic for a given Seed.
 *
 * Like an image read from a file, the images have origin (0,0,0) and spacing (1,1,1):
 * texel (i, j) is at (i, j, 0), row j = 0 being the bottom row (texture v grows with j).
 */
#ifndef vtkProceduralReliefSource_h
#define vtkProceduralReliefSource_h

#include "MesolightReliefTexturesModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkProceduralReliefSource : public vtkImageAlgorithm
{
public:
  static vtkProceduralReliefSource* New();
  vtkTypeMacro(vtkProceduralReliefSource, vtkImageAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum PatternType
  {
    BRICKS = 0,
    STONE,
    HEMISPHERE_TORUS,
    FLAT,
    SINE_WAVE,
    NUMBER_OF_PATTERNS
  };

  ///@{
  /**
   * Pattern to generate. Default is HEMISPHERE_TORUS.
   */
  vtkSetClampMacro(Pattern, int, BRICKS, SINE_WAVE);
  vtkGetMacro(Pattern, int);
  void SetPatternToBricks() { this->SetPattern(BRICKS); }
  void SetPatternToStone() { this->SetPattern(STONE); }
  void SetPatternToHemisphereTorus() { this->SetPattern(HEMISPHERE_TORUS); }
  void SetPatternToFlat() { this->SetPattern(FLAT); }
  void SetPatternToSineWave() { this->SetPattern(SINE_WAVE); }
  ///@}

  /**
   * Name of a pattern ("Bricks", "Stone", "HemisphereTorus", "Flat", "SineWave"), or
   * nullptr for an invalid value.
   */
  static const char* GetPatternName(int pattern);

  /**
   * Set the pattern from its name (case-insensitive). Returns false, with an error, and
   * leaves the pattern unchanged if the name is unknown.
   */
  bool SetPatternByName(const char* name);

  ///@{
  /**
   * Number of texels along x (u) and y (v). Each is clamped to [1, 16384].
   * Default is 256 x 256.
   */
  void SetResolution(int w, int h);
  void SetResolution(const int res[2]) { this->SetResolution(res[0], res[1]); }
  vtkGetVector2Macro(Resolution, int);
  ///@}

  ///@{
  /**
   * Seed of the hash noise (Bricks, Stone). Default is 0.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Depth of the Flat pattern, in [0,1]. Default is 0.5.
   */
  vtkSetClampMacro(FlatDepth, double, 0.0, 1.0);
  vtkGetMacro(FlatDepth, double);
  ///@}

  ///@{
  /**
   * Integer frequencies (fx, fy) of the SineWave pattern. Default is (1, 1).
   */
  vtkSetVector2Macro(SineFrequency, int);
  vtkGetVector2Macro(SineFrequency, int);
  ///@}

  ///@{
  /**
   * Bricks layout: number of brick courses (along v, clamped to [1, 4096], default 8),
   * bricks per course (along u, clamped to [1, 4096], default 4) and the mortar joint
   * width as a fraction of the brick height (clamped to [0, 0.9], default 0.15).
   */
  vtkSetClampMacro(BrickRows, int, 1, 4096);
  vtkGetMacro(BrickRows, int);
  vtkSetClampMacro(BrickColumns, int, 1, 4096);
  vtkGetMacro(BrickColumns, int);
  vtkSetClampMacro(MortarWidth, double, 0.0, 0.9);
  vtkGetMacro(MortarWidth, double);
  ///@}

  ///@{
  /**
   * Number of fBm octaves of the Stone pattern, clamped to [1, 12]. Default is 6.
   */
  vtkSetClampMacro(StoneOctaves, int, 1, 12);
  vtkGetMacro(StoneOctaves, int);
  ///@}

  /// Convenience accessors for the two outputs.
  vtkImageData* GetDepthOutput() { return this->GetOutput(0); }
  vtkImageData* GetAlbedoOutput() { return this->GetOutput(1); }

protected:
  vtkProceduralReliefSource();
  ~vtkProceduralReliefSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Pattern = HEMISPHERE_TORUS;
  int Resolution[2] = { 256, 256 };
  unsigned int Seed = 0;
  double FlatDepth = 0.5;
  int SineFrequency[2] = { 1, 1 };
  int BrickRows = 8;
  int BrickColumns = 4;
  double MortarWidth = 0.15;
  int StoneOctaves = 6;

private:
  vtkProceduralReliefSource(const vtkProceduralReliefSource&) = delete;
  void operator=(const vtkProceduralReliefSource&) = delete;
};

#endif
