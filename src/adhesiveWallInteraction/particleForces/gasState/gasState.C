// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "gasState.H"
#include "checkedInput.H"
#include "Plausibility.H"

namespace
{

Foam::scalar readPositive
(
    const Foam::dictionary& dict,
    const Foam::word& keyword
)
{
    const Foam::scalar value = Foam::checkedInput::readNumber(dict, keyword);
    if (!(value > 0))
    {
        Foam::checkedInput::fail
        (
            dict, keyword, Foam::checkedInput::entryText(*Foam::checkedInput::find(dict, keyword)),
            "must be > 0"
        );
    }
    return value;
}


//- A positive value of the gas's state; one that can only be a unit
//  mistake stops the run unless the force's extremeValues takes it (then,
//  as the model's, it is warned about)
Foam::scalar readGasValue
(
    const Foam::dictionary& dict,
    const Foam::word& keyword,
    const brachDunn::Magnitude& m
)
{
    using namespace Foam;
    const scalar value = checkedInput::readNumber(dict, keyword);
    const bool extreme = checkedInput::readSwitch(dict, "extremeValues", false);
    // A value not > 0 must be > 0, unless it is a unit mistake whose value
    // meant the magnitude check names (T 0: 0 degC); taken as given
    // (extremeValues) is no way past > 0
    const bool mistakeNamed =
        !brachDunn::unitMistake(m, keyword, value).empty()
     && !brachDunn::meant(m, value).empty();
    if (!(value > 0) && (extreme || !mistakeNamed))
    {
        readPositive(dict, keyword);
    }
    const std::string warning = checkedInput::checkMagnitude
    (
        dict, keyword, value, m, extreme,
        "extremeValues yes in " + dict.dictName()
    );
    if (!warning.empty())
    {
        WarningInFunction
            << "In dictionary " << dict.name() << ": " << warning.c_str()
            << endl;
    }
    return value;
}

} // End anonymous namespace


Foam::scalar Foam::aerosolForces::readTemperature
(
    const dictionary& dict,
    const bool carrierHasTemperature
)
{
    const bool given = checkedInput::find(dict, "T") != nullptr;
    if (carrierHasTemperature)
    {
        if (given)
        {
            checkedInput::fail
            (
                dict, "T", checkedInput::entryText(*checkedInput::find(dict, "T")),
                "is not read in a thermo cloud: the carrier's temperature "
                "at the parcel is used (remove T)"
            );
        }
        return -1;
    }
    if (!given)
    {
        checkedInput::fail
        (
            dict, "T", "(missing)",
            "the gas temperature [K] is required: this cloud has no "
            "carrier temperature"
        );
    }
    return readGasValue(dict, "T", brachDunn::magnitude::temperature);
}


Foam::scalar Foam::aerosolForces::meanFreePathSource::at
(
    const scalar T,
    const scalar mu,
    const scalar pressure
) const
{
    return
        given >= 0
      ? given
      : brachDunn::meanFreePath(mu, pressure, T, molarMass);
}


Foam::aerosolForces::meanFreePathSource
Foam::aerosolForces::readMeanFreePath
(
    const dictionary& dict,
    const bool carrierHasPressure
)
{
    meanFreePathSource source;
    const bool given = checkedInput::find(dict, "meanFreePath") != nullptr;
    const bool fromP = checkedInput::find(dict, "p") != nullptr;
    if (carrierHasPressure && fromP)
    {
        checkedInput::fail
        (
            dict, "p", checkedInput::entryText(*checkedInput::find(dict, "p")),
            "is not read in a thermo cloud: the carrier's pressure at the "
            "parcel is used (remove p)"
        );
    }
    if (!carrierHasPressure && given == fromP)
    {
        checkedInput::fail
        (
            dict, given ? "meanFreePath" : "meanFreePath or p",
            given ? "given with p" : "(missing)",
            "give either meanFreePath [m] or the pressure p [Pa] (with T "
            "and molarMass, from which the mean free path follows)"
        );
    }
    if (given && checkedInput::find(dict, "molarMass"))
    {
        checkedInput::fail
        (
            dict, "molarMass",
            checkedInput::entryText(*checkedInput::find(dict, "molarMass")),
            "is given with meanFreePath, which it would not change: the molar"
            " mass only serves to compute the mean free path from p and T."
            " Remove one"
        );
    }
    if (given)
    {
        source.given = readGasValue
        (
            dict, "meanFreePath", brachDunn::magnitude::meanFreePath
        );
    }
    else
    {
        if (!carrierHasPressure)
        {
            source.p = readGasValue(dict, "p", brachDunn::magnitude::pressure);
        }
        if (checkedInput::find(dict, "molarMass"))
        {
            source.molarMass = readGasValue
            (
                dict, "molarMass", brachDunn::magnitude::molarMass
            );
        }
    }
    return source;
}


::brachDunn::SlipCoefficients
Foam::aerosolForces::readSlipCoefficients(const dictionary& dict)
{
    if (!checkedInput::find(dict, "slipCoefficients"))
    {
        return brachDunn::daviesSlip;
    }
    const word name = checkedInput::readWord(dict, "slipCoefficients");
    return checkedInput::coreCall
    (
        dict, [&]{ return brachDunn::slipCoefficients(name); }
    );
}


void Foam::aerosolForces::stopWithoutDrag
(
    const char* force,
    const label origId,
    const scalar Sp
)
{
    FatalErrorInFunction
        << force << " needs a drag (sphereDrag, slipSphereDrag, or another "
        << "implicit coupled force) in particleForces: the friction of "
        << "parcel " << origId << " is " << Sp << nl
        << exit(FatalError);
}


void Foam::aerosolForces::stopInSubCycles
(
    const char* force,
    const scalar moved,
    const scalar trackTime
)
{
    FatalErrorInFunction
        << force << ": the parcels are moved over " << moved
        << " s at a time, not over the cloud's time step " << trackTime
        << " s: the collision model moves them in sub-cycles, and "
        << force << " draws its random numbers for whole time steps (use "
        << "collisionModel none)" << nl << exit(FatalError);
}


// ************************************************************************* //
