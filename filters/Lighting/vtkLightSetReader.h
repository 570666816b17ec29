// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightSetReader
 * @brief   reads a light set written by vtkMedianCutLights::WriteCsv (`mesolight lights`)
 *
 * The CSV has the header "u,v,x,y,z,r,g,b" and one row per light: map coordinates, unit
 * direction (+Z up, the light is at infinity in that direction) and irradiance at normal
 * incidence (RGB). The outputs are those of vtkMedianCutLights, so a light set read back
 * replaces the filter anywhere (vtkReliefMapper::SetLightSetConnection, vtkLightSetLighting):
 *  - port 0, vtkPolyData: one vertex per light at its direction, point data "Irradiance"
 *    (float RGB), "MapCoordinates" (float u, v) and "SolidAngle" (0: the CSV does not carry it);
 *  - port 1 (GetLightTexture()), the N x 2 float RGBA light texture "Lights": row 0 the
 *    directions (x, y, z, 0), row 1 the irradiances (r, g, b, 0).
 * Rows keep the file's order. Values are read as doubles and stored as the filter stores them
 * (points double, arrays float), so a write and a read give the filter's values to float
 * precision.
 *
 * Errors (vtkErrorMacro, no output, never a crash): no file name; a file that cannot be opened;
 * an empty file; a wrong header; a row with more or fewer than 8 fields, a field that is not a
 * number, NaN or infinite; a direction that is not of unit length (within 1e-3); a negative
 * irradiance; a file without lights. Each message names the file and the line.
 */
#ifndef vtkLightSetReader_h
#define vtkLightSetReader_h

#include "MesolightLightingModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;

class MESOLIGHTLIGHTING_EXPORT vtkLightSetReader : public vtkPolyDataAlgorithm
{
public:
  static vtkLightSetReader* New();
  vtkTypeMacro(vtkLightSetReader, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The CSV file to read. */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /** The N x 2 light texture (output port 1). */
  vtkImageData* GetLightTexture();

  /**
   * Parses a light-set CSV without a pipeline: 8 numbers per light (u, v, x, y, z, r, g, b)
   * appended to `values`. False with a one-line message (file and line named) on any error.
   */
  static bool ParseCsv(
    const std::string& fileName, std::vector<double>& values, std::string& error);

protected:
  vtkLightSetReader();
  ~vtkLightSetReader() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  std::vector<double> Values; // parsed in RequestInformation (the texture's extent needs N)

  vtkLightSetReader(const vtkLightSetReader&) = delete;
  void operator=(const vtkLightSetReader&) = delete;
};

#endif
