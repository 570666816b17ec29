// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOIIOImageWriter
 * @brief   write vtkImageData with OpenImageIO (PNG, TIFF, EXR, HDR, JPEG, ...)
 *
 * vtkOIIOImageWriter writes the point scalars (1 to 4 components) of a 2D image. The file
 * format comes from the FileName extension. The stored pixel type is chosen by DataType:
 * - AUTO (default): .exr / .hdr (and other float formats) -> float; integer formats
 *   (.png, .tif, .jpg, ...) -> 8 bit, or 16 bit for PNG/TIFF when BitDepth is 16;
 * - UNSIGNED_CHAR, UNSIGNED_SHORT, FLOAT: forced.
 * Values are converted through [0,1] (uchar / 255, ushort / 65535, float as is) and
 * quantized with rounding and clamping (NaN -> 0). Float to float is exact.
 *
 * Rows are flipped back to the file's top-first order (VTK row 0 is the bottom row, it
 * becomes the file's last row). Alpha is written as is (unassociated): relief textures keep
 * the depth in A.
 *
 * The image is first written to a temporary file in the target directory and then renamed
 * over FileName, so a failed write never leaves a broken file behind.
 *
 * Call Write() (or Update()). Errors set ErrorCode and report the file name and the
 * OpenImageIO message.
 */
#ifndef vtkOIIOImageWriter_h
#define vtkOIIOImageWriter_h

#include "MesolightImageIOModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTIMAGEIO_EXPORT vtkOIIOImageWriter : public vtkImageAlgorithm
{
public:
  static vtkOIIOImageWriter* New();
  vtkTypeMacro(vtkOIIOImageWriter, vtkImageAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DataTypes
  {
    AUTO = 0,
    UNSIGNED_CHAR,
    UNSIGNED_SHORT,
    FLOAT
  };

  ///@{
  /**
   * Name of the file to write; its extension selects the format.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Pixel type stored in the file. Default is AUTO.
   */
  vtkSetClampMacro(DataType, int, AUTO, FLOAT);
  vtkGetMacro(DataType, int);
  void SetDataTypeToAuto() { this->SetDataType(AUTO); }
  void SetDataTypeToUnsignedChar() { this->SetDataType(UNSIGNED_CHAR); }
  void SetDataTypeToUnsignedShort() { this->SetDataType(UNSIGNED_SHORT); }
  void SetDataTypeToFloat() { this->SetDataType(FLOAT); }
  ///@}

  ///@{
  /**
   * Bit depth used by AUTO for PNG and TIFF files: 8 or 16 (clamped). Default is 8.
   */
  vtkSetClampMacro(BitDepth, int, 8, 16);
  vtkGetMacro(BitDepth, int);
  ///@}

  /**
   * Write the input to FileName. Returns true on success.
   */
  bool Write();

protected:
  vtkOIIOImageWriter();
  ~vtkOIIOImageWriter() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  int DataType = AUTO;
  int BitDepth = 8;

private:
  bool LastWriteSucceeded = false;

  vtkOIIOImageWriter(const vtkOIIOImageWriter&) = delete;
  void operator=(const vtkOIIOImageWriter&) = delete;

  bool WriteImage(vtkImageData* input);
  static bool ProgressCallback(void* self, float portionDone);
};

#endif
