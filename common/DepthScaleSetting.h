// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DepthScaleSetting.h
 * @brief How every Mesolight setter takes a relief's depth scale (the rule in plain C++17;
 *        the setter body for VTK classes a template on VTK's message macros).
 *
 * One rule for vtkReliefProperty and vtkReliefTextureFilter, so that a user's mistake gets the
 * same answer wherever it is made: NaN is refused (the old value is kept), anything else is
 * clamped to [0, maximum], and a value that was changed is said, with what to do instead. A
 * negative scale is the common case: it reads as "make the light parts high", which is the
 * depth map inverted, not a negative depth.
 */
#ifndef mesolight_DepthScaleSetting_h
#define mesolight_DepthScaleSetting_h

#include "vtkObject.h" // vtkErrorWithObjectMacro, vtkWarningWithObjectMacro (SetDepthScaleOf)

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace mesolight
{

/// The largest depth scale anything accepts (the world depth of depth 1 over the texture's world
/// width): a relief ten times deeper than wide. vtkReliefProperty, vtkReliefTextureFilter (also
/// for its true scale times VerticalExaggeration) and the shader's baked scale use it alike.
constexpr double MaximumDepthScale = 10.0;

/// False for NaN (value untouched). Otherwise value = requested clamped to [0, maximum], and
/// note the sentence to report when it differs from requested (empty when it does not).
inline bool ClampDepthScale(double requested, double maximum, double& value, std::string& note)
{
  note.clear();
  if (std::isnan(requested))
  {
    note = "NaN is not a depth scale";
    return false;
  }
  value = std::min(std::max(requested, 0.0), maximum);
  std::ostringstream text;
  if (requested < 0.0)
  {
    text << "The depth scale " << requested
         << " is taken as 0 (a flat surface): depth scales are not negative. To raise the light "
            "parts of the depth map instead of the dark ones, invert it (vtkReliefTextureFilter "
            "InvertInput; ParaView: Mesolight Relief Texture's Invert Input).";
  }
  else if (requested > maximum)
  {
    text << "The depth scale " << requested << " is clamped to " << maximum
         << " (the world depth of depth 1 over the texture's world width).";
  }
  note = text.str();
  return true;
}

/// A depth-scale setter's whole body, for VTK classes (Object: a vtkObject): ClampDepthScale,
/// its note reported through the object's error or warning, `member` set and the object
/// modified when the value changes.
template <class Object>
void SetDepthScaleOf(Object* self, double& member, double requested, double maximum)
{
  double value = member;
  std::string note;
  if (!ClampDepthScale(requested, maximum, value, note))
  {
    vtkErrorWithObjectMacro(self, << "SetDepthScale: " << note << "; keeping " << member << ".");
    return;
  }
  if (!note.empty())
  {
    vtkWarningWithObjectMacro(self, << "SetDepthScale: " << note);
  }
  if (value != member)
  {
    member = value;
    self->Modified();
  }
}

} // namespace mesolight

#endif
