#include "fw/model/expressions.hpp"

#include <gtest/gtest.h>

namespace fw::model {
namespace {

TEST(Expressions, EveryNameIsKnown) {
  for (std::size_t e = 0; e < kExpressionCount; ++e)
    EXPECT_EQ(expression_from_name(kExpressionNames[e]), static_cast<Expression>(e));
  EXPECT_FALSE(expression_from_name("boredom").has_value());
}

TEST(Expressions, AngerIsTheSyntaxDirectedPapersSentence) {
  codec::FaceParams p;
  apply_expression(Expression::anger, 1.0f, p);
  for (int au : {2, 4, 5, 7, 15, 17, 20, 23, 26}) EXPECT_GT(p.au_intensity(au), 0.0f) << "AU " << au;
  EXPECT_FLOAT_EQ(p.au_intensity(4), 1.0f) << "its strongest unit (2.0 on the paper's scale)";
  EXPECT_FLOAT_EQ(p.au_intensity(12), 0.0f);
}

TEST(Expressions, IntensityScalesAndBlendsByMaximum) {
  codec::FaceParams half, both;
  apply_expression(Expression::joy, 0.5f, half);
  EXPECT_FLOAT_EQ(half.au_intensity(12), 0.5f);
  apply_expression(Expression::joy, 0.5f, both);
  apply_expression(Expression::surprise, 1.0f, both);
  EXPECT_FLOAT_EQ(both.au_intensity(12), 0.5f) << "joy's smile kept";
  EXPECT_FLOAT_EQ(both.au_intensity(26), 0.8f) << "surprise's jaw added";
}

TEST(Expressions, TeasingIsOneSidedAndCunningNarrowsTheLids) {
  codec::FaceParams teasing, cunning;
  apply_expression(Expression::teasing, 1.0f, teasing);
  EXPECT_GT(teasing.au_intensity(12, codec::AuSide::left), 0.5f);
  EXPECT_FLOAT_EQ(teasing.au_intensity(12, codec::AuSide::right), 0.0f);
  apply_expression(Expression::cunning, 1.0f, cunning);
  EXPECT_GT(cunning.lid_left, 0.3f);
  EXPECT_GT(cunning.au_intensity(12), 0.0f);
}

}  // namespace
}  // namespace fw::model
