// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "LeastSquares.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace brachDunn
{

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace
{

using Model = std::function<VectorXd(const VectorXd&)>;

//- Central differences; one-sided where the other side leaves the model's
//  range (a coefficient at its bound, as an exponent at 0)
MatrixXd jacobian(const Model& model, const VectorXd& t, const VectorXd& at)
{
    MatrixXd J(at.size(), t.size());
    for (int j = 0; j < t.size(); ++j)
    {
        const double h = 1e-6*std::max(std::abs(t(j)), 1e-3);
        VectorXd up = t, down = t;
        up(j) += h;
        down(j) -= h;
        const VectorXd above = model(up), below = model(down);
        const bool upFinite = above.allFinite();
        const bool downFinite = below.allFinite();
        if (upFinite && downFinite)
        {
            J.col(j) = (above - below)/(2*h);
        }
        else if (upFinite)
        {
            J.col(j) = (above - at)/h;
        }
        else
        {
            J.col(j) = (at - below)/h;
        }
    }
    return J;
}


//- The Levenberg-Marquardt trial point from theta, of the damped normal
//  equations (A + lambda diag(A)) step = -g, projected; a parameter the
//  projection holds where it is (at a bound the step leaves) is held out of
//  the step, so that the others take a proper step of their own
VectorXd trialPoint
(
    const MatrixXd& A,
    const VectorXd& g,
    double lambda,
    const VectorXd& theta,
    const Projection& project
)
{
    MatrixXd damped = A;
    damped.diagonal() += lambda*A.diagonal().cwiseMax(1e-300);
    const VectorXd step = -damped.ldlt().solve(g);
    const VectorXd trial = project(theta + step);
    VectorXd free = g;
    bool held = false;
    for (int i = 0; i < theta.size(); ++i)
    {
        if (trial(i) == theta(i) && step(i) != 0)
        {
            held = true;
            damped.row(i).setZero();
            damped.col(i).setZero();
            damped(i, i) = 1;
            free(i) = 0;
        }
    }
    return held ? project(theta - damped.ldlt().solve(free)) : trial;
}


//- Levenberg-Marquardt iterations from theta; the sum of squared residuals
//  at the end
double minimise
(
    const Model& model,
    const VectorXd& y,
    VectorXd& theta,
    const Projection& project
)
{
    const auto rss = [&](const VectorXd& t)
    {
        const double s = (model(t) - y).squaredNorm();
        return std::isfinite(s) ? s : HUGE_VAL;
    };
    double lambda = 1e-3;
    double current = rss(theta);
    VectorXd at = model(theta);
    MatrixXd J = jacobian(model, theta, at);
    for (int iter = 0; iter < 500; ++iter)
    {
        const VectorXd trial = trialPoint
        (
            J.transpose()*J, J.transpose()*(at - y), lambda, theta, project
        );
        const double next = rss(trial);
        if (next < current)
        {
            const bool settled =
                (trial - theta).norm() <= 1e-13*(theta.norm() + 1e-13)
             || current - next <= 1e-14*current;
            theta = trial;
            current = next;
            lambda = std::max(lambda/10, 1e-12);
            if (settled) break;
            at = model(theta);
            J = jacobian(model, theta, at);
        }
        else
        {
            lambda *= 10;
            if (lambda > 1e12) break;
        }
    }
    return current;
}

} // End anonymous namespace


LeastSquares levenbergMarquardt
(
    const Model& model,
    const VectorXd& y,
    VectorXd theta,
    const Projection& project
)
{
    const int n = y.size(), p = theta.size();
    const double rss = minimise(model, y, theta, project);
    const VectorXd fitted = model(theta);

    // The covariance through the SVD of J with its columns scaled to unit
    // length, so that the rank test does not depend on the parameters'
    // units: a column of zeros, or one that is a combination of the others
    // to 1e-7, leaves the parameters undetermined
    const MatrixXd J = jacobian(model, theta, fitted);
    const VectorXd scale = J.colwise().norm().transpose();
    if (!(scale.minCoeff() > 0) || !J.allFinite())
    {
        return {theta, VectorXd::Zero(p), fitted, false, n - p, rss};
    }
    const Eigen::JacobiSVD<MatrixXd> svd
    (
        J*scale.cwiseInverse().asDiagonal(), Eigen::ComputeThinV
    );
    const VectorXd sigma = svd.singularValues();
    if (!(sigma(p - 1) > 1e-7*sigma(0)))
    {
        return {theta, VectorXd::Zero(p), fitted, false, n - p, rss};
    }
    const double s2 = n > p ? rss/(n - p) : 0;
    const MatrixXd V =
        scale.cwiseInverse().asDiagonal()*svd.matrixV()
       *sigma.cwiseInverse().asDiagonal();
    const VectorXd variance = s2*V.rowwise().squaredNorm();
    return {theta, variance.cwiseSqrt(), fitted, true, n - p, rss};
}


double pearson(const VectorXd& a, const VectorXd& b)
{
    const VectorXd da = a.array() - a.mean();
    const VectorXd db = b.array() - b.mean();
    const double denominator = da.norm()*db.norm();
    return denominator > 0 ? da.dot(db)/denominator : 0;
}


double incompleteBeta(double a, double b, double x)
{
    if (!(a > 0 && b > 0 && x >= 0 && x <= 1))
    {
        throw std::domain_error("incompleteBeta: a, b > 0, 0 <= x <= 1");
    }
    if (x == 0 || x == 1) return x;
    // The continued fraction converges fast for x < (a + 1)/(a + b + 2);
    // beyond, I_x(a, b) = 1 - I_(1-x)(b, a)
    if (x > (a + 1)/(a + b + 2))
    {
        return 1 - incompleteBeta(b, a, 1 - x);
    }
    const double front = std::exp
    (
        std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b)
      + a*std::log(x) + b*std::log1p(-x)
    )/a;

    // Lentz's method on 1/(1 + d1/(1 + d2/(1 + ...)))
    const double tiny = 1e-300;
    double f = 1, c = 1, d = 0;
    for (int i = 0; i <= 400; ++i)
    {
        const int m = i/2;
        const double numerator =
            i == 0 ? 1
          : i % 2 == 0 ? m*(b - m)*x/((a + 2*m - 1)*(a + 2*m))
          : -(a + m)*(a + b + m)*x/((a + 2*m)*(a + 2*m + 1));
        d = 1 + numerator*d;
        d = 1/(std::abs(d) < tiny ? tiny : d);
        c = 1 + numerator/c;
        c = std::abs(c) < tiny ? tiny : c;
        f *= c*d;
        if (std::abs(1 - c*d) < 1e-15) break;
    }
    return front*(f - 1);
}


double studentT(double t, int dof)
{
    if (dof < 1)
    {
        throw std::domain_error("studentT: dof must be >= 1");
    }
    const double tail = 0.5*incompleteBeta(0.5*dof, 0.5, dof/(dof + t*t));
    return t > 0 ? 1 - tail : tail;
}


double studentTQuantile(double probability, int dof)
{
    if (!(probability > 0 && probability < 1) || dof < 1)
    {
        throw std::domain_error
        (
            "studentTQuantile: 0 < probability < 1, dof >= 1"
        );
    }
    if (probability < 0.5) return -studentTQuantile(1 - probability, dof);
    double low = 0, high = 1;
    while (studentT(high, dof) < probability) high *= 2;
    for (int i = 0; i < 200 && high - low > 1e-13*high; ++i)
    {
        const double middle = 0.5*(low + high);
        (studentT(middle, dof) < probability ? low : high) = middle;
    }
    return 0.5*(low + high);
}

} // End namespace brachDunn
