// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// nearWallDispersion's checks of the cloud, the flow and its walks
// (NearWallDispersionForce.H), included by NearWallDispersionForce.C

template<class CloudType>
void Foam::NearWallDispersionForce<CloudType>::checkCloud() const
{
    const word dispersion = this->owner().dispersion().type();
    if (dispersion != "none")
    {
        FatalErrorInFunction
            << "nearWallDispersion keeps its state in the parcels' UTurb "
            << "and tTurb: the cloud's dispersionModel must be none, not "
            << dispersion << exit(FatalError);
    }
    for (const auto& force : this->owner().forces())
    {
        const word type = force.type();
        if (type == "exactBrownianMotion" || type == "BrownianMotion")
        {
            FatalErrorInFunction
                << "nearWallDispersion and " << type << " both keep a "
                << "parcel's state in UTurb and tTurb: select one of them "
                << "(Brownian and turbulent motion together are not built "
                << "yet)" << exit(FatalError);
        }
    }
    checked_ = true;
}


template<class CloudType>
void Foam::NearWallDispersionForce<CloudType>::checkFlow() const
{
    const CloudType& cloud = this->owner();
    // A wall-resolved mesh: the walls' first cell centres in the viscous
    // sublayer, where the mean velocity interpolated to the wall is the
    // law of the wall's (the near-wall statistics come from the fits on
    // any mesh; the mean velocity seen is OpenFOAM's interpolation)
    for (const fvPatch& patch : this->mesh().boundary())
    {
        if (!isA<wallPolyPatch>(patch.patch()))
        {
            continue;
        }
        scalar largest = 0;
        for (const label celli : patch.faceCells())
        {
            const scalar nu = cloud.mu()[celli]/cloud.rho()[celli];
            largest = max
            (
                largest,
                units_->y()[celli]*units_->uStar()[celli]/nu
            );
        }
        reduce(largest, maxOp<scalar>());
        if (largest > maxFirstCellYPlus)
        {
            FatalErrorInFunction
                << "nearWallDispersion needs a wall-resolved mesh: the "
                << "cell centres next to wall patch " << patch.name()
                << " lie at y+ up to " << largest << ", and must lie at "
                << "y+ <= " << maxFirstCellYPlus << " (the viscous "
                << "sublayer, where the carrier velocity interpolated to "
                << "the wall follows the law of the wall; a wall-function "
                << "mesh is not supported: refine the walls' first cells)"
                << exit(FatalError);
        }
    }
}


template<class CloudType>
void Foam::NearWallDispersionForce<CloudType>::reportLeastSubSteps() const
{
    const label n = returnReduce(leastSubSteps_, sumOp<label>());
    leastSubSteps_ = 0;
    if (n > 0)
    {
        WarningInFunction
            << "nearWallDispersion: " << n << " sub-steps of cloud "
            << this->owner().name() << " in this time step took walks "
            << "bounded by maxSubSteps " << path_.maxSubSteps
            << " (their time scales wanted shorter sub-steps of the walk; "
            << "harmless where the RANS k is tiny, a still region; near a "
            << "wall, shorten the time step or raise maxSubSteps)" << endl;
    }
}


// ************************************************************************* //
