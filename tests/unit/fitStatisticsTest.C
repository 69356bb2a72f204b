// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The statistics of the coefficient fits: Student's t distribution and its
// quantile (the 95 % intervals of impactFit) against printed table values
// and closed forms, the regularised incomplete beta function against
// identities, and the bounded Levenberg-Marquardt fit.

#include "LeastSquares.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace brachDunn;

TEST(StudentT, QuantilesAreThoseOfTheTables)
{
    // Two-sided 95 % (0.975) and 99 % (0.995) points, e.g. Abramowitz &
    // Stegun Table 26.10, to the digits printed there
    const struct { double p; int dof; double t; } table[] =
    {
        {0.975, 1, 12.706}, {0.975, 2, 4.303}, {0.975, 3, 3.182},
        {0.975, 5, 2.5706}, {0.975, 10, 2.2281}, {0.975, 30, 2.0423},
        {0.975, 120, 1.9799}, {0.995, 10, 3.1693}, {0.95, 4, 2.1318}
    };
    for (const auto& row : table)
    {
        EXPECT_NEAR(studentTQuantile(row.p, row.dof), row.t, 6e-4)
            << "t(" << row.p << ", " << row.dof << ")";
    }
    // Symmetric about 0; the normal 1.95996 as dof grows
    EXPECT_NEAR(studentTQuantile(0.025, 5), -2.5706, 6e-4);
    EXPECT_NEAR(studentTQuantile(0.5, 7), 0, 1e-12);
    EXPECT_NEAR(studentTQuantile(0.975, 100000), 1.959964, 1e-4);
}


TEST(StudentT, DistributionHasItsClosedForms)
{
    // dof 1 is Cauchy's, 0.5 + atan(t)/pi; dof 2 is 0.5 + t/(2 sqrt(2 + t^2))
    for (const double t : {-30.0, -2.0, -0.3, 0.0, 0.7, 4.0, 100.0})
    {
        EXPECT_NEAR(studentT(t, 1), 0.5 + std::atan(t)/M_PI, 1e-13) << t;
        EXPECT_NEAR(studentT(t, 2), 0.5 + t/(2*std::sqrt(2 + t*t)), 1e-13)
            << t;
    }
    // The quantile inverts the distribution
    for (const int dof : {1, 2, 4, 9, 40})
    {
        for (const double p : {0.6, 0.9, 0.975, 0.999})
        {
            EXPECT_NEAR(studentT(studentTQuantile(p, dof), dof), p, 1e-12);
        }
    }
}


TEST(StudentT, IncompleteBetaIdentities)
{
    for (const double x : {0.0, 0.01, 0.3, 0.5, 0.77, 0.999, 1.0})
    {
        EXPECT_NEAR(incompleteBeta(1, 1, x), x, 1e-14) << x;
        EXPECT_NEAR(incompleteBeta(3.5, 1, x), std::pow(x, 3.5), 1e-14) << x;
        EXPECT_NEAR(incompleteBeta(1, 2.5, x), 1 - std::pow(1 - x, 2.5), 1e-14);
        EXPECT_NEAR
        (
            incompleteBeta(2.2, 0.7, x), 1 - incompleteBeta(0.7, 2.2, 1 - x),
            1e-14
        );
    }
    EXPECT_NEAR(incompleteBeta(4, 4, 0.5), 0.5, 1e-14);
    EXPECT_THROW(incompleteBeta(0, 1, 0.5), std::domain_error);
    EXPECT_THROW(studentTQuantile(1, 3), std::domain_error);
    EXPECT_THROW(studentTQuantile(0.975, 0), std::domain_error);
}


TEST(LeastSquares, ABoundHoldsOneParameterNotTheOthers)
{
    // y = a + b x with b >= 0 on data falling with x: the best fit holds b
    // at 0 and a at the mean, which a step of b beyond the bound must not
    // stop
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(6, 0, 5);
    const Eigen::VectorXd y = 3 - 0.2*x.array();
    const LeastSquares fit = levenbergMarquardt
    (
        [&](const Eigen::VectorXd& t)
        {
            return Eigen::VectorXd(t(0) + t(1)*x.array());
        },
        y,
        Eigen::Vector2d(10, 1),
        [](const Eigen::VectorXd& t)
        {
            return Eigen::Vector2d(t(0), std::max(t(1), 0.0));
        }
    );
    EXPECT_EQ(fit.theta(1), 0);
    EXPECT_NEAR(fit.theta(0), y.mean(), 1e-9);
    EXPECT_EQ(fit.degreesOfFreedom, 4);
}


TEST(LeastSquares, ALineHasTheTextbookStandardErrors)
{
    // y = a + b x: se(b) = s/sqrt(Sxx), se(a) = s sqrt(1/n + xbar^2/Sxx)
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(7, 1, 7);
    Eigen::VectorXd y(7);
    y << 2.1, 3.9, 6.2, 7.8, 10.1, 12.2, 13.8;
    const LeastSquares fit = levenbergMarquardt
    (
        [&](const Eigen::VectorXd& t)
        {
            return Eigen::VectorXd(t(0) + t(1)*x.array());
        },
        y,
        Eigen::Vector2d(0, 0)
    );
    const double n = 7, xbar = x.mean();
    const double sxx = (x.array() - xbar).square().sum();
    const double b = ((x.array() - xbar)*(y.array() - y.mean())).sum()/sxx;
    const double a = y.mean() - b*xbar;
    const double s2 = (y.array() - a - b*x.array()).square().sum()/(n - 2);
    EXPECT_NEAR(fit.theta(1), b, 1e-9);
    EXPECT_NEAR(fit.theta(0), a, 1e-9);
    EXPECT_NEAR(fit.standardErrors(1), std::sqrt(s2/sxx), 1e-7);
    EXPECT_NEAR
    (
        fit.standardErrors(0), std::sqrt(s2*(1/n + xbar*xbar/sxx)), 1e-7
    );
    EXPECT_TRUE(fit.determined);
    EXPECT_NEAR(fit.rss, s2*(n - 2), 1e-12);
}


TEST(LeastSquares, ParametersTheDataCannotTellApartAreUndetermined)
{
    // y = a b x: only the product a b is determined
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(5, 1, 5);
    const LeastSquares fit = levenbergMarquardt
    (
        [&](const Eigen::VectorXd& t)
        {
            return Eigen::VectorXd(t(0)*t(1)*x.array());
        },
        2*x,
        Eigen::Vector2d(1, 1)
    );
    EXPECT_FALSE(fit.determined);
}
