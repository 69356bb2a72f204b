// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "ExactBrownianMotionForce.H"
#include "BrownianStep.H"
#include "CounterRandom.H"
#include "SlipCorrection.H"
#include "checkedInput.H"
#include "gasState.H"
#include "releaseCompat.H"

#include <cmath>

template<class CloudType>
Foam::ExactBrownianMotionForce<CloudType>::ExactBrownianMotionForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    T_
    (
        aerosolForces::readTemperature
        (
            checkedInput::withKnownKeywords
            (
                this->coeffs(), {"T", "seed", "extremeValues"},
                "exactBrownianMotion"
            ),
            aerosolForces::carrierHasTemperature<CloudType>
        )
    ),
    seed_(checkedInput::readCount(this->coeffs(), "seed", 0)),
    drawTrackTime_(-1)
{
    Info<< "    exactBrownianMotion: "
        << (
               T_ > 0
             ? "T " + aerosolForces::text(T_) + " K"
             : std::string("the carrier's temperature at each parcel")
           ).c_str()
        << ", seed " << label(seed_) << endl;
}


template<class CloudType>
void Foam::ExactBrownianMotionForce<CloudType>::drawStep
(
    const typename CloudType::parcelType& p,
    const std::uint64_t draw,
    const vector& V0,
    const scales& s,
    vector& X,
    vector& V
) const
{
    brachDunn::CounterRandom random
    (
        seed_,
        static_cast<std::uint64_t>(static_cast<std::int64_t>(p.origProc())),
        static_cast<std::uint64_t>(static_cast<std::int64_t>(p.origId())),
        draw
    );

    vector start = V0;
    if (draw == 0)
    {
        // A thermal start: the parcel in equilibrium with the gas
        const scalar sigma = std::sqrt(s.thermalVariance);
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            start[i] = sigma*random.normal();
        }
    }

    const brachDunn::BrownianTransition transition =
        brachDunn::brownianTransition
        (
            drawTrackTime_, s.tau, s.thermalVariance
        );
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        const scalar z1 = random.normal();
        const scalar z2 = random.normal();
        const brachDunn::BrownianSample sample =
            brachDunn::sampleBrownian(transition, start[i], z1, z2);
        X[i] = sample.displacement;
        V[i] = sample.velocity;
    }
}


template<class CloudType>
void Foam::ExactBrownianMotionForce<CloudType>::checkCloud
(
    const scalar trackTime
) const
{
    if (drawTrackTime_ < 0)
    {
        const word dispersion = this->owner().dispersion().type();
        if (dispersion != "none")
        {
            FatalErrorInFunction
                << "exactBrownianMotion: dispersionModel " << dispersion
                << ": must be none (exactBrownianMotion keeps a parcel's "
                << "Brownian state where the dispersion models keep theirs)"
                << nl << exit(FatalError);
        }
        const auto& forces = this->owner().forces();
        forAll(forces, i)
        {
            if (forces[i].type() == "BrownianMotion")
            {
                FatalErrorInFunction
                    << "exactBrownianMotion: particleForces also selects "
                    << "BrownianMotion: Brownian motion would be counted "
                    << "twice (select one)" << nl << exit(FatalError);
            }
        }
    }

    if (drawTrackTime_ < 0)
    {
        drawTrackTime_ = trackTime;
    }
    else if (mag(trackTime - drawTrackTime_) > 1e-12*drawTrackTime_)
    {
        FatalErrorInFunction
            << "exactBrownianMotion: the cloud's time step changed from "
            << drawTrackTime_ << " s to " << trackTime << " s: the Brownian "
            << "step is drawn for a fixed time step (set adjustTimeStep no "
            << "and keep deltaT)" << nl << exit(FatalError);
    }
    // Moved in sub-cycles of the time step (a colliding cloud's collision
    // subCycles; checked at every completed step, as the cloud may move
    // its parcels over the whole step first): a sub-cycle would complete
    // the step of the draws
    aerosolForces::checkWholeSteps(this->owner(), "exactBrownianMotion");
}


template<class CloudType>
typename Foam::ExactBrownianMotionForce<CloudType>::scales
Foam::ExactBrownianMotionForce<CloudType>::scalesOf
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    const scalar Sp = aerosolForces::dragFriction
    (
        this->owner(), p, td, dt, mass, Re, muc, "exactBrownianMotion"
    );
    const scalar massEff = this->owner().forces().massEff(p, td, mass);
    return
    {
        Sp,
        massEff,
        massEff/Sp,
        brachDunn::boltzmann*aerosolForces::temperatureAt(T_, td)/massEff
    };
}


template<class CloudType>
std::uint64_t Foam::ExactBrownianMotionForce<CloudType>::drawsTaken
(
    const typename CloudType::parcelType& p,
    const scalar draws
)
{
    // (whole numbers: exact at any writePrecision up to a million steps)
    if (!std::isfinite(draws) || draws != std::floor(draws))
    {
        FatalErrorInFunction
            << "exactBrownianMotion: parcel " << p.origId() << " of "
            << "processor " << p.origProc() << " carries tTurb = " << draws
            << ", not a count of Brownian draws (was the case run with a "
            << "dispersion model?)" << nl << exit(FatalError);
    }
    return static_cast<std::uint64_t>(draws < 0 ? -draws - 1 : draws);
}


template<class CloudType>
Foam::forceSuSp Foam::ExactBrownianMotionForce<CloudType>::calcNonCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    forceSuSp value(Zero);
    if (!compat::isActive(p))
    {
        return value;
    }
    const scales s = scalesOf(p, td, dt, mass, Re, muc);
    const scalar trackTime = this->owner().solution().trackTime();
    if (drawTrackTime_ < 0)
    {
        checkCloud(trackTime);
    }

    // The parcel's state: its tTurb counts the draws (drawsTaken) and its
    // UTurb holds the velocity V0 the current draw starts from
    scalar& draws = compat::walkScalar(p);
    vector& V0 = compat::walkVector(p);
    const bool pending = draws < 0;
    std::uint64_t count = drawsTaken(p, draws);

    // The Brownian velocity held over this step: the current draw's
    // displacement over the step (none before the first draw)
    vector W(Zero), V(Zero);
    if (count > 0)
    {
        vector X;
        drawStep(p, count - 1, V0, s, X, V);
        W = X/drawTrackTime_;
    }

    // The draw of the step that ended is taken into the state in the
    // sub-step that starts the next: not when the step was completed, as
    // a contact at the surface can take the parcel back into that step,
    // which it then completes again (one transition a step either way)
    if (pending && p.stepFraction() - dt/trackTime < 1e-9)
    {
        V0 = V;
        draws = ++count;
        vector X;
        drawStep(p, count - 1, V0, s, X, V);
        W = X/drawTrackTime_;
    }
    value.Su() = s.Sp*W;

    // The sub-step that completes the time step draws the next step and
    // sets the held velocity to it (the impulse is exact for the cloud's
    // integration scheme: U -> U + (alpha - beta U) dtEff); a sub-step of
    // the rounding left after it (dt of order 1e-16 of the step) does not
    if (p.stepFraction() >= 1 - 1e-9 && dt > 1e-9*trackTime)
    {
        checkCloud(trackTime);
        vector Xnext, Vnext;
        drawStep(p, count, V, s, Xnext, Vnext);
        const scalar dtEff =
            this->owner().UIntegrator().dtEff(dt, s.Sp/s.massEff);
        value.Su() += s.massEff*(Xnext/drawTrackTime_ - W)/dtEff;
        draws = -scalar(count) - 1;
    }
    return value;
}
