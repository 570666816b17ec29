// Shared helpers of the integration tests.
#ifndef mesolight_TestReliefTestUtilities_h
#define mesolight_TestReliefTestUtilities_h

#include <vtkCommand.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <string>

class vtkImageData;
class vtkObject;

namespace mesolight
{
namespace test
{

/** Records error and warning events of the objects it observes. */
class MessageRecorder : public vtkCommand
{
public:
  static MessageRecorder* New() { return new MessageRecorder; }
  void Execute(vtkObject* caller, unsigned long event, void* callData) override;
  /** Observes errors and warnings of object (and keeps them from the console). */
  void Watch(vtkObject* object);
  std::string Errors;
  std::string Warnings;
};

/** A depth map sampled at texel centres from depth(u, v) in [0,1]. */
vtkSmartPointer<vtkImageData> MakeDepthMap(
  int width, int height, const std::function<double(double, double)>& depth);

/** The relief texture of a depth map (vtkReliefTextureFilter, clamp borders). */
vtkSmartPointer<vtkImageData> BakeRelief(vtkImageData* depth, double depthScale);

/** Where test output goes (a build-tree directory). */
std::string OutputPath(const std::string& name);

} // namespace test
} // namespace mesolight

#endif
