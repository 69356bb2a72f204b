// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// AdhesiveWallSurfaceContact: what it checks of the case and of parcels
// (included by AdhesiveWallSurfaceContact.C)

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkMaxDiameter() const
{
    // 20 typed for 20 um: a search to 10 m from every cell. Taken as
    // given (extremeValues), it is said; the impact model's range of
    // diameters is not the search's concern
    const std::string warning = checkedInput::checkMagnitude
    (
        this->coeffDict(), "maxDiameter", maxDiameter_,
        brachDunn::magnitude::diameter, model_->extremeValues()
    );
    if
    (
        !brachDunn::unitMistake
        (
            brachDunn::magnitude::diameter, "maxDiameter", maxDiameter_
        ).empty()
    )
    {
        WarningInFunction
            << "In dictionary " << this->coeffDict().name() << ": "
            << warning.c_str() << endl;
    }

    // Smaller than an injector's size: known now, not only when such a
    // parcel moves; far larger: the search costs memory and time for
    // nothing
    scalar largest = 0;
    wallInteractionCloud::forEachInjectorSize
    (
        this->owner(),
        [&](const dictionary& dict, const word& key, const scalar d)
        {
            if (d > maxDiameter_)
            {
                checkedInput::fail
                (
                    this->coeffDict(), "maxDiameter", name(maxDiameter_),
                    "at least the largest diameter of the parcels: "
                  + dict.name() + '.' + key + " is " + name(d) + " m"
                );
            }
            largest = max(largest, d);
        }
    );
    if (largest > 0 && maxDiameter_ > 10*largest)
    {
        WarningInFunction
            << "Cloud function " << this->modelName() << ": maxDiameter "
            << maxDiameter_ << " m is more than ten times the largest"
            << " diameter the injectors name (" << largest << " m); the"
            << " wall search reaches maxDiameter/2 from every cell, which"
            << " costs memory and time. Set it to the largest diameter of"
            << " the parcels" << endl;
    }
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkOnlyMoves() const
{
    const std::string why =
        ": contact at the surface moves a parcel back to where it touched a"
        " wall, and OpenFOAM has by then exchanged the whole sub-step with"
        " the carrier and the parcel (calc before the cloud functions'"
        " postMove); the part taken back would count twice. Contact at the"
        " surface is for clouds whose sub-steps only move their parcels:"
        " remove " + this->modelName() + " from cloudFunctions (contact at"
        " the centre) or ";
    const cloudSolution& solution = this->owner().solution();
    if (solution.coupled())
    {
        checkedInput::fail
        (
            solution.dict(), "coupled",
            checkedInput::entryText(*checkedInput::find(solution.dict(), "coupled")),
            "two-way coupling" + why + "set coupled false (one-way coupling,"
            " as in dilute aerosols)"
        );
    }
    const dictionary& subModels = this->owner().subModelProperties();
    if (checkedInput::readSwitch(subModels, "radiation", false))
    {
        checkedInput::fail
        (
            subModels, "radiation",
            checkedInput::entryText(*checkedInput::find(subModels, "radiation")),
            "the parcels' radiation" + why + "set radiation off"
        );
    }
    for
    (
        const char* keyword :
        {
            "heatTransferModel", "phaseChangeModel", "devolatilisationModel",
            "surfaceReactionModel", "heterogeneousReactingModel",
            "atomizationModel", "breakupModel"
        }
    )
    {
        if
        (
            checkedInput::find(subModels, keyword)
         && checkedInput::readWord(subModels, keyword) != "none"
        )
        {
            checkedInput::fail
            (
                subModels, keyword, checkedInput::readWord(subModels, keyword),
                "changes the parcels' temperature, mass or size over a"
                " sub-step" + why + "set " + keyword + " none"
            );
        }
    }
}


template<class CloudType>
Foam::scalar Foam::AdhesiveWallSurfaceContact<CloudType>::readMaxDiameter
(
    const dictionary& dict
)
{
    checkedInput::requireKnownKeywords
    (
        dict, {"type", "maxDiameter"},
        "cloud function adhesiveWallSurfaceContact"
    );
    const scalar maxDiameter = checkedInput::readNumber(dict, "maxDiameter");
    if (!(maxDiameter > 0))
    {
        checkedInput::fail
        (
            dict, "maxDiameter", name(maxDiameter), "a diameter > 0 [m]"
        );
    }
    return maxDiameter;
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::stopTooLarge
(
    const typename CloudType::parcelType& p
) const
{
    FatalErrorInFunction
        << "Cloud function " << this->modelName() << " of cloud "
        << this->owner().name() << ": a parcel of diameter " << p.d()
        << " m at " << compat::position(p, this->owner().mesh())
        << " is larger than maxDiameter " << maxDiameter_
        << " m, so walls it touches could be missed. Set maxDiameter to"
        << " the largest diameter the parcels reach (spray parcels grow as"
        << " they heat)" << exit(FatalError);
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkPosition
(
    const typename CloudType::parcelType& p,
    const point& end
) const
{
    const point exact = compat::position(p, this->owner().mesh());
    if (end.x() != exact.x() || end.y() != exact.y() || end.z() != exact.z())
    {
        FatalErrorInFunction
            << "Cloud function " << this->modelName() << " of cloud "
            << this->owner().name() << ": the position from the parcel's tet "
            << setprecision(17) << end << " differs from OpenFOAM's " << exact
            << " (cell " << p.cell() << ", face " << p.tetFace()
            << ", tet point " << p.tetPt() << ")" << exit(FatalError);
    }
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkMovingWalls() const
{
    // A wall face held here for another processor has no velocity here:
    // its contacts would take the wall as still (the result would depend
    // on the decomposition). Moving walls (a lid, a belt: the tangential
    // velocity their U condition sets) are refused in parallel runs
    if (!Pstream::parRun() || !returnReduce(walls_->nRemote(), sumOp<label>()))
    {
        return;
    }
    const polyBoundaryMesh& patches = compat::boundaryMesh(this->owner().mesh());
    for (const label patchi : model_->wallPatches())
    {
        const fvPatchVectorField& Uw = this->owner().U().boundaryField()[patchi];
        const scalar speed =
            isA<wallPolyPatch>(patches[patchi]) && Uw.fixesValue() && Uw.size()
          ? max(mag(Uw)) : 0;
        const scalar fastest = returnReduce(speed, maxOp<scalar>());
        if (fastest > 0)
        {
            FatalErrorInFunction
                << "Cloud function " << this->modelName() << " of cloud "
                << this->owner().name() << ": wall patch "
                << patches[patchi].name() << " moves (its U condition sets "
                << "up to " << fastest << " m/s) in a parallel run, and contact at the surface"
                << " takes the faces it holds for a neighbouring processor as"
                << " still. Run this case in serial, or without "
                << this->modelName() << " (contact at the centre)"
                << exit(FatalError);
        }
    }
}


// ************************************************************************* //
