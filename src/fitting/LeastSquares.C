// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "LeastSquares.H"

#include <algorithm>
#include <cmath>

namespace brachDunn
{

using Eigen::MatrixXd;
using Eigen::VectorXd;

LeastSquares levenbergMarquardt
(
    const std::function<VectorXd(const VectorXd&)>& model,
    const VectorXd& y,
    VectorXd theta
)
{
    const int n = y.size(), p = theta.size();
    const auto rss = [&](const VectorXd& t)
    {
        const double s = (model(t) - y).squaredNorm();
        return std::isfinite(s) ? s : HUGE_VAL;
    };
    // Central differences; one-sided where the other side leaves the
    // model's range (a coefficient at its bound, as an exponent at 0)
    const auto jacobian = [&](const VectorXd& t)
    {
        const VectorXd at = model(t);
        MatrixXd J(n, p);
        for (int j = 0; j < p; ++j)
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
    };

    double lambda = 1e-3;
    double current = rss(theta);
    for (int iter = 0; iter < 500; ++iter)
    {
        const MatrixXd J = jacobian(theta);
        const MatrixXd A = J.transpose()*J;
        const VectorXd g = J.transpose()*(model(theta) - y);
        MatrixXd damped = A;
        damped.diagonal() += lambda*A.diagonal().cwiseMax(1e-300);
        const VectorXd step = -damped.ldlt().solve(g);
        const VectorXd trial = theta + step;
        const double next = rss(trial);
        if (next < current)
        {
            const bool settled =
                step.norm() <= 1e-13*(theta.norm() + 1e-13)
             || current - next <= 1e-16*current;
            theta = trial;
            current = next;
            lambda = std::max(lambda/10, 1e-12);
            if (settled) break;
        }
        else
        {
            lambda *= 10;
            if (lambda > 1e12) break;
        }
    }

    const MatrixXd J = jacobian(theta);
    const Eigen::FullPivLU<MatrixXd> lu(J.transpose()*J);
    if (lu.rank() < p)
    {
        // A coefficient does not move the model (e.g. held at its bound)
        return {theta, VectorXd::Zero(p), model(theta), false};
    }
    const double s2 = n > p ? current/(n - p) : 0;
    const MatrixXd covariance = s2*lu.inverse();
    return {theta, covariance.diagonal().cwiseSqrt(), model(theta), true};
}


double pearson(const VectorXd& a, const VectorXd& b)
{
    const VectorXd da = a.array() - a.mean();
    const VectorXd db = b.array() - b.mean();
    const double denominator = da.norm()*db.norm();
    return denominator > 0 ? da.dot(db)/denominator : 0;
}

} // End namespace brachDunn
