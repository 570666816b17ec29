// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkDepthHallucinationFilter
 * @brief   Diffuse-lit + flash-lit photographs -> albedo and a hallucinated depth map.
 *
 * Depth hallucination after Glencross et al., "A perceptually validated model for surface
 * depth hallucination" (SIGGRAPH 2008), as in Méndez Fernández's thesis ch. 3. The model, and
 * where it simplifies the paper, is described in filters/ReliefTextures/core/DepthHallucination.h
 * and measured in docs/hallucination.md.
 *
 * Inputs (vtkImageData, same dimensions, linear light; 1, 3 or 4 components, the first three
 * read as RGB; unsigned char / short scale to [0, 1]):
 *  - port 0: the diffuse photograph (overcast sky or shade), I_d;
 *  - port 1: the flash photograph of the same view under the same light plus a flash at the
 *    camera, I_f;
 *  - port 2 (optional): a flash photograph of a white card filling the view, I_c (the flash's
 *    fall-off and vignetting). Without it the flash is taken as uniform (I_c = 1).
 * Outputs:
 *  - port 0: albedo (I_f - I_d) / I_c, float RGB ("Albedo");
 *  - port 1: depth, float ("Depth"), 0 = highest point, 1 = deepest (the project's convention),
 *    with field data "MesolightDepthScale" = the model's depth of Depth 1 divided by the image
 *    width (the relief DepthScale convention) and "HallucinatedDepthRangeTexels".
 * Errors (vtkErrorMacro, empty outputs): an empty input, photographs of different sizes, NaN or
 * infinite pixels, a flash image darker than the diffuse one. Reports progress and honours
 * AbortExecute.
 */
#ifndef vtkDepthHallucinationFilter_h
#define vtkDepthHallucinationFilter_h

#include "MesolightReliefTexturesModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkDepthHallucinationFilter : public vtkImageAlgorithm
{
public:
  static vtkDepthHallucinationFilter* New();
  vtkTypeMacro(vtkDepthHallucinationFilter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Connections by role (ports 0, 1, 2). */
  void SetDiffuseConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetFlashConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetCalibrationConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }
  ///@}

  ///@{
  /** The user's depth scale: multiplies the model's depth (default 1). */
  vtkSetClampMacro(DepthScale, double, 1e-6, 1e6);
  vtkGetMacro(DepthScale, double);
  ///@}

  ///@{
  /**
   * Scale layers (1..12); -2 (the default): from the ratio image's feature size, the scale
   * average on fine features and one wide count on broad ones (HallucinationSettings::Layers;
   * with UseRatio 0 the scale average); 0: the scale average, every layer count the
   * photograph holds averaged; -1: one count chosen from the photographs' octave energies.
   * The first has sigma BaseSigma texels, each next doubles.
   */
  vtkSetClampMacro(NumberOfLayers, int, -2, 12);
  vtkGetMacro(NumberOfLayers, int);
  vtkSetClampMacro(BaseSigma, double, 0.1, 1000.0);
  vtkGetMacro(BaseSigma, double);
  ///@}

  ///@{
  /**
   * 1 (the default): the layers read the diffuse/flash ratio and the scale average weighs each
   * layer count by its agreement with it (HallucinationModel::Ratio); 0: the previous model, the
   * layers read the shading and every count has an equal say (HallucinationModel::Shading).
   */
  vtkSetClampMacro(UseRatio, int, 0, 1);
  vtkGetMacro(UseRatio, int);
  vtkBooleanMacro(UseRatio, int);
  ///@}

  ///@{
  /** Weights of the valley (visible aperture) and hill (orientation to the sky) laws. */
  vtkSetClampMacro(ValleyWeight, double, 0.0, 100.0);
  vtkGetMacro(ValleyWeight, double);
  vtkSetClampMacro(HillWeight, double, 0.0, 100.0);
  vtkGetMacro(HillWeight, double);
  ///@}

  ///@{
  /**
   * Sigma of the residual layer (the widest layer against the open sky) in units of the widest
   * layer's; 0: none (default 8).
   */
  vtkSetClampMacro(ResidualWeight, double, 0.0, 100.0);
  vtkGetMacro(ResidualWeight, double);
  ///@}

  /** The model's depth of Depth = 1 in texels after the last update (0 before). */
  vtkGetMacro(DepthRangeTexels, double);
  /** The layers the last update used (NumberOfLayers, or the automatic choice; 0 before). */
  vtkGetMacro(LayersUsed, int);
  /** The feature size the automatic choice measured, texels (0 when the layers were given). */
  vtkGetMacro(FeatureSizeTexels, double);
  /** 1 when the last update averaged the counts 1..LayersUsed (the scale average). */
  vtkGetMacro(LayersAveraged, int);
  /** NumberOfLayers -2: the ratio image's autocorrelation length, texels (0 otherwise). */
  vtkGetMacro(CorrelationLengthTexels, double);

  vtkImageData* GetAlbedoOutput();
  vtkImageData* GetDepthOutput();

protected:
  vtkDepthHallucinationFilter();
  ~vtkDepthHallucinationFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double DepthScale = 1.0;
  int NumberOfLayers = -2;
  int UseRatio = 1;
  double BaseSigma = 1.0;
  double ValleyWeight = 1.0;
  double HillWeight = 1.0;
  double ResidualWeight = 8.0;
  double DepthRangeTexels = 0.0;
  int LayersUsed = 0;
  double FeatureSizeTexels = 0.0;
  int LayersAveraged = 0;
  double CorrelationLengthTexels = 0.0;

private:
  vtkDepthHallucinationFilter(const vtkDepthHallucinationFilter&) = delete;
  void operator=(const vtkDepthHallucinationFilter&) = delete;
};

#endif
