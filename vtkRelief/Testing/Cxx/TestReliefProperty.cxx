// SPDX-License-Identifier: BSD-3-Clause
// Unit tests for vtkReliefProperty: the one method-name table, and one property shared by
// several mappers (no GPU needed).

#include "MessageCapture.h"
#include "VTKMessage.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkVersionMacros.h>

#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositeReliefMapper.h"
#endif

#include <gtest/gtest.h>

#include <cmath>
#include <string>

TEST(ReliefProperty, MethodNamesRoundTrip)
{
  for (int m = 0; m < vtkReliefProperty::NumberOfMethods; ++m)
  {
    const char* name = vtkReliefProperty::GetMethodName(m);
    EXPECT_EQ(vtkReliefProperty::GetMethodFromName(name), m) << name;
    vtkNew<vtkReliefProperty> property;
    property->SetMethod(m == 0 ? 1 : 0);
    EXPECT_TRUE(property->SetMethodByName(name)) << name;
    EXPECT_EQ(property->GetMethod(), m) << name;
  }
  EXPECT_STREQ(vtkReliefProperty::GetMethodName(vtkReliefProperty::Relief), "relief");
  EXPECT_STREQ(vtkReliefProperty::GetMethodName(vtkReliefProperty::ParallaxOcclusion), "pom");
  EXPECT_STREQ(vtkReliefProperty::GetMethodName(vtkReliefProperty::MaximumMipmap), "max-mipmap");
}

TEST(ReliefProperty, NormalFilterNamesRoundTrip)
{
  for (int f = vtkReliefProperty::MeanNormalFilter; f <= vtkReliefProperty::MaskedNormalFilter; ++f)
  {
    const char* name = vtkReliefProperty::GetNormalFilterName(f);
    EXPECT_EQ(vtkReliefProperty::GetNormalFilterFromName(name), f) << name;
  }
  EXPECT_STREQ(
    vtkReliefProperty::GetNormalFilterName(vtkReliefProperty::MaskedNormalFilter), "masked");
  EXPECT_STREQ(vtkReliefProperty::GetNormalFilterName(3), "unknown");
  EXPECT_EQ(vtkReliefProperty::GetNormalFilterFromName("toksvig"), -1);
  EXPECT_EQ(vtkReliefProperty::GetNormalFilterFromName(nullptr), -1);
}

TEST(ReliefProperty, SteepIsLinearSearch)
{
  EXPECT_EQ(vtkReliefProperty::GetMethodFromName("steep"), vtkReliefProperty::LinearSearch);
  EXPECT_EQ(vtkReliefProperty::GetMethodFromName("linear"), vtkReliefProperty::LinearSearch);
  vtkNew<vtkReliefProperty> property;
  EXPECT_TRUE(property->SetMethodByName("steep"));
  EXPECT_EQ(property->GetMethod(), vtkReliefProperty::LinearSearch);
  property->SetMethodToRelief();
  property->SetMethodToSteepParallax();
  EXPECT_EQ(property->GetMethod(), vtkReliefProperty::LinearSearch);
}

TEST(ReliefProperty, UnknownNamesAreRefused)
{
  EXPECT_EQ(vtkReliefProperty::GetMethodFromName("no-such-method"), -1);
  EXPECT_EQ(vtkReliefProperty::GetMethodFromName(""), -1);
  EXPECT_EQ(vtkReliefProperty::GetMethodFromName(nullptr), -1);
  EXPECT_EQ(vtkReliefProperty::GetMethodFromName("Relief"), -1) << "names are case-sensitive";
  vtkNew<vtkReliefProperty> property;
  property->SetMethod(vtkReliefProperty::Interval);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(property);
  EXPECT_FALSE(property->SetMethodByName("no-such-method"));
  // Said, with the names to pick from, not refused in silence.
  EXPECT_TRUE(messages->HasError("Unknown relief method 'no-such-method'"))
    << messages->AllErrors();
  EXPECT_TRUE(messages->HasError("relief, interval")) << messages->AllErrors();
  EXPECT_TRUE(messages->HasError("max-mipmap")) << messages->AllErrors();
  EXPECT_FALSE(property->SetMethodByName(nullptr));
  EXPECT_EQ(property->GetMethod(), vtkReliefProperty::Interval) << "the method is kept";
  property->SetMethodToMaximumMipmap();
  EXPECT_EQ(property->GetMethod(), vtkReliefProperty::MaximumMipmap);
  EXPECT_STREQ(vtkReliefProperty::GetMethodName(-1), "unknown");
  EXPECT_STREQ(vtkReliefProperty::GetMethodName(vtkReliefProperty::NumberOfMethods), "unknown");
}

// A depth limit plane without a direction (or with NaN/Inf) is an error; the plane set before
// stays.
TEST(ReliefProperty, DepthLimitPlaneNeedsANormal)
{
  vtkNew<vtkReliefProperty> property;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(property);
  const double origin[3] = { 0.0, 0.0, 1.0 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double nan[3] = { std::nan(""), 0.0, 1.0 };
  property->SetDepthLimitPlane(origin, zero);
  EXPECT_TRUE(messages->HasError("non-zero finite normal")) << messages->AllErrors();
  EXPECT_FALSE(property->GetHasDepthLimitPlane());
  property->SetDepthLimitPlane(origin, up);
  EXPECT_TRUE(property->GetHasDepthLimitPlane());
  property->SetDepthLimitPlane(nan, up);
  property->SetDepthLimitPlane(origin, nan);
  EXPECT_TRUE(property->GetHasDepthLimitPlane());
  EXPECT_EQ(property->GetDepthLimitNormal()[2], 1.0) << "the earlier plane is kept";
  EXPECT_EQ(property->GetDepthLimitOrigin()[0], 0.0);
}

TEST(ReliefProperty, RequiredConeMaps)
{
  EXPECT_EQ(vtkReliefProperty::GetRequiredConeMap(vtkReliefProperty::RelaxedConeBinary),
    vtkReliefProperty::RelaxedConeMap);
  EXPECT_EQ(vtkReliefProperty::GetRequiredConeMap(vtkReliefProperty::RelaxedConeInterval),
    vtkReliefProperty::RelaxedConeMap);
  EXPECT_EQ(vtkReliefProperty::GetRequiredConeMap(vtkReliefProperty::ConservativeCone),
    vtkReliefProperty::ConservativeConeMap);
  EXPECT_EQ(
    vtkReliefProperty::GetRequiredConeMap(vtkReliefProperty::Relief), vtkReliefProperty::NoConeMap);
  EXPECT_EQ(vtkReliefProperty::GetRequiredConeMap(vtkReliefProperty::MaximumMipmap),
    vtkReliefProperty::NoConeMap);
}

TEST(ReliefProperty, DefaultsAndClamping)
{
  vtkNew<vtkReliefProperty> property;
  // The exact traversal by default (docs/relief-methods.md, "The default is exact").
  EXPECT_EQ(property->GetMethod(), vtkReliefProperty::MaximumMipmap);
  EXPECT_EQ(property->GetLinearSteps(), 64);
  EXPECT_EQ(property->GetRefinementSteps(), 8);
  EXPECT_EQ(property->GetDepthScale(), 0.05);
  EXPECT_TRUE(property->GetSelfShadowing());
  EXPECT_EQ(property->GetOutput(), vtkReliefProperty::ShadedOutput);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(property);
  // Clamped into range, and said (VTK's vtkSetClampMacro clamped without a word).
  property->SetMethod(1000);
  EXPECT_EQ(property->GetMethod(), vtkReliefProperty::NumberOfMethods - 1);
  EXPECT_TRUE(messages->HasWarning("SetMethod: 1000 is outside [0, ")) << messages->AllWarnings();
  property->SetLinearSteps(0);
  EXPECT_EQ(property->GetLinearSteps(), 1);
  EXPECT_TRUE(messages->HasWarning("SetLinearSteps: 0 is outside [1, 1024]; using 1."))
    << messages->AllWarnings();
  property->SetExposure(-1.0);
  EXPECT_EQ(property->GetExposure(), 0.0);
  EXPECT_TRUE(messages->HasWarning("SetExposure: -1 is outside")) << messages->AllWarnings();
  // NaN is refused, the old value kept.
  property->SetExposure(2.0);
  property->SetExposure(std::nan(""));
  EXPECT_EQ(property->GetExposure(), 2.0);
  EXPECT_TRUE(messages->HasError("SetExposure: NaN is not a value; keeping 2."))
    << messages->AllErrors();
  // In range: nothing said.
  messages->Clear();
  property->SetLinearSteps(32);
  property->SetRefinementSteps(8);
  EXPECT_TRUE(messages->AllWarnings().empty()) << messages->AllWarnings();
  EXPECT_EQ(property->GetLinearStepsMaxValue(), 1024);
  property->SetDepthScale(-1.0);
  EXPECT_EQ(property->GetDepthScale(), 0.0);
  // Said, with what a negative scale was likely meant for.
  EXPECT_TRUE(messages->HasWarning("is taken as 0")) << messages->AllWarnings();
  EXPECT_TRUE(messages->HasWarning("invert it")) << messages->AllWarnings();
  messages->Clear();
  property->SetDepthScale(0.2);
  EXPECT_TRUE(messages->AllWarnings().empty()) << messages->AllWarnings();
  property->SetDepthScale(50.0);
  EXPECT_EQ(property->GetDepthScale(), 10.0);
  EXPECT_TRUE(messages->HasWarning("clamped to 10")) << messages->AllWarnings();
}

TEST(ReliefProperty, SharedByTwoMappers)
{
  vtkNew<vtkReliefMapper> first;
  vtkNew<vtkReliefMapper> second;
  second->SetReliefProperty(first->GetReliefProperty());
  ASSERT_EQ(first->GetReliefProperty(), second->GetReliefProperty());

  const vtkMTimeType firstBefore = first->GetMTime();
  const vtkMTimeType secondBefore = second->GetMTime();
  first->GetReliefProperty()->SetLinearSteps(32);
  EXPECT_GT(first->GetMTime(), firstBefore);
  EXPECT_GT(second->GetMTime(), secondBefore);
  EXPECT_EQ(second->GetReliefProperty()->GetLinearSteps(), 32);

  // A property made on its own and given to both, as a representation does.
  vtkNew<vtkReliefProperty> shared;
  first->SetReliefProperty(shared);
  second->SetReliefProperty(shared);
  const vtkMTimeType firstMiddle = first->GetMTime();
  const vtkMTimeType secondMiddle = second->GetMTime();
  shared->SetMethodByName("pom");
  EXPECT_GT(first->GetMTime(), firstMiddle);
  EXPECT_GT(second->GetMTime(), secondMiddle);
  EXPECT_EQ(first->GetReliefProperty()->GetMethod(), vtkReliefProperty::ParallaxOcclusion);

  // An unchanged setting changes no modification time.
  const vtkMTimeType firstAfter = first->GetMTime();
  shared->SetMethodByName("pom");
  EXPECT_EQ(first->GetMTime(), firstAfter);

  // Null gives the mapper a new default property of its own.
  second->SetReliefProperty(nullptr);
  ASSERT_NE(second->GetReliefProperty(), nullptr);
  EXPECT_NE(second->GetReliefProperty(), shared.Get());
  EXPECT_EQ(second->GetReliefProperty()->GetMethod(), vtkReliefProperty::MaximumMipmap);
}

#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 0)
TEST(ReliefProperty, SharedByReliefAndCompositeMappers)
{
  vtkNew<vtkReliefMapper> plain;
  vtkNew<vtkCompositeReliefMapper> composite;
  composite->SetReliefProperty(plain->GetReliefProperty());
  const vtkMTimeType before = composite->GetMTime();
  plain->GetReliefProperty()->SetDepthScale(0.2);
  EXPECT_GT(composite->GetMTime(), before);
  EXPECT_EQ(composite->GetReliefProperty()->GetDepthScale(), 0.2);
}
#endif

TEST(ReliefProperty, ErrorsReachTheObserversOfTheMapperThatMadeIt)
{
  vtkNew<vtkReliefMapper> mapper;
  vtkNew<mesolight_test::MessageCapture> errors;
  errors->Watch(mapper);
  mapper->GetReliefProperty()->SetDepthScale(0.2);
  mapper->GetReliefProperty()->SetDepthScale(std::nan(""));
  EXPECT_EQ(mapper->GetReliefProperty()->GetDepthScale(), 0.2);
  ASSERT_EQ(errors->Errors.size(), 1u) << errors->AllErrors();
  // What a user is shown of it: VTK's location line and object prefix dropped.
  EXPECT_EQ(mesolight::CleanVTKMessage(errors->Errors[0]),
    "SetDepthScale: NaN is not a depth scale; keeping 0.2.");
  EXPECT_EQ(mesolight::CleanVTKMessage("plain text\n\n"), "plain text");

  // The owner is not referenced: a property outliving its mapper has none.
  vtkSmartPointer<vtkReliefProperty> kept = mapper->GetReliefProperty();
  EXPECT_EQ(kept->GetMessageOwner(), mapper.Get());
  {
    vtkNew<vtkReliefMapper> other;
    kept = other->GetReliefProperty();
    EXPECT_EQ(kept->GetMessageOwner(), other.Get());
  }
  EXPECT_EQ(kept->GetMessageOwner(), nullptr);
}
