// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "SlipSphereDragForce.H"
#include "checkedInput.H"

template<class CloudType>
Foam::scalar Foam::SlipSphereDragForce<CloudType>::CdRe(const scalar Re)
{
    return Re > 1000 ? 0.424*Re : 24*(1 + cbrt(sqr(Re))/6);
}


template<class CloudType>
Foam::SlipSphereDragForce<CloudType>::SlipSphereDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    coefficients_
    (
        aerosolForces::readSlipCoefficients
        (
            checkedInput::withKnownKeywords
            (
                this->coeffs(),
                {
                    "slipCoefficients", "meanFreePath", "p", "T",
                    "molarMass", "extremeValues"
                },
                "slipSphereDrag"
            )
        )
    ),
    meanFreePath_
    (
        aerosolForces::readMeanFreePath
        (
            this->coeffs(), aerosolForces::carrierHasTemperature<CloudType>
        )
    ),
    T_(-1)
{
    const dictionary& coeffs = this->coeffs();
    if (meanFreePath_.given < 0)
    {
        T_ = aerosolForces::readTemperature
        (
            coeffs, aerosolForces::carrierHasTemperature<CloudType>
        );
    }
    else if (checkedInput::find(coeffs, "T"))
    {
        checkedInput::fail
        (
            coeffs, "T", checkedInput::entryText(*checkedInput::find(coeffs, "T")),
            "is not read with meanFreePath (T goes with p)"
        );
    }

    Info<< "    slipSphereDrag: " << describe().c_str() << endl;
    checkOnlyDrag(owner);
}


template<class CloudType>
std::string Foam::SlipSphereDragForce<CloudType>::describe() const
{
    // (as the model prints its settings, numbers in their shortest exact
    // form)
    const dictionary& coeffs = this->coeffs();
    using aerosolForces::text;
    std::string settings =
        (
            checkedInput::find(coeffs, "slipCoefficients")
          ? checkedInput::readWord(coeffs, "slipCoefficients")
          : word("Davies")
        )
      + " slip (A1 " + text(coefficients_.A1) + ", A2 "
      + text(coefficients_.A2) + ", A3 " + text(coefficients_.A3)
      + "), mean free path ";
    if (meanFreePath_.given >= 0)
    {
        settings += text(meanFreePath_.given) + " m";
    }
    else
    {
        settings +=
            "from "
          + (
                meanFreePath_.p > 0
              ? "p " + text(meanFreePath_.p) + " Pa"
              : std::string("the carrier's pressure")
            )
          + ", "
          + (T_ > 0 ? "T " + text(T_) + " K" : "the carrier's temperature")
          + ", molar mass " + text(meanFreePath_.molarMass)
          + " kg/mol and the carrier's viscosity";
    }
    return settings;
}


template<class CloudType>
void Foam::SlipSphereDragForce<CloudType>::checkOnlyDrag
(
    const CloudType& owner
)
{
    // It is the drag: another drag law beside it (sphereDrag left in when
    // switching) would double the drag and halve exactBrownianMotion's
    // diffusivity kT/Sp, with nothing in the log (OpenFOAM's drag forces
    // are all named ...Drag)
    const dictionary& forces =
        owner.subModelProperties().subOrEmptyDict("particleForces");
    for (const entry& force : forces)
    {
        const word& name = force.keyword();
        if
        (
            name != typeName && name.size() >= 4
         && name.compare(name.size() - 4, 4, "Drag") == 0
        )
        {
            checkedInput::fail
            (
                forces, name, checkedInput::entryText(force),
                "another drag law beside slipSphereDrag, which is the drag"
                " (with slip): the drag would count twice. Remove " + name
              + " from particleForces"
            );
        }
    }
}


template<class CloudType>
Foam::scalar Foam::SlipSphereDragForce<CloudType>::slipCorrection
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar muc
) const
{
    if (meanFreePath_.given >= 0)
    {
        return brachDunn::cunningham(p.d(), meanFreePath_.given, coefficients_);
    }
    // (the gas's state looked up only where it is used)
    const scalar T = aerosolForces::temperatureAt(T_, td);
    const scalar pressure =
        aerosolForces::pressureAt(meanFreePath_.p, this->owner(), p, td);
    const scalar lambda = meanFreePath_.at(T, muc, pressure);
    if (debug)
    {
        // (DebugSwitches { slipSphereDrag 1; }: what a parcel's drag took)
        Pout<< "slipSphereDrag: cell " << p.cell() << " p " << pressure
            << " Pa T " << T << " K mean free path " << lambda << " m"
            << endl;
    }
    return brachDunn::cunningham(p.d(), lambda, coefficients_);
}


template<class CloudType>
Foam::forceSuSp Foam::SlipSphereDragForce<CloudType>::calcCoupled
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
    value.Sp() =
        mass*0.75*muc*CdRe(Re)/(p.rho()*sqr(p.d()))
       /slipCorrection(p, td, muc);
    return value;
}
