// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "carrierTurbulence.H"
#include COMPAT_TURBULENCE_MODEL_H

Foam::carrierTurbulence::carrierTurbulence(const volVectorField& U)
:
    model_(nullptr),
    turbulent_(false)
{
    const auto models =
        U.mesh().thisDb().lookupClass<compat::turbulenceModel>();
    forAllConstIters(models, iter)
    {
        const compat::turbulenceModel& model = *iter();
        if (&model.U() == &U)
        {
            model_ = &model;
        }
    }
    if (model_)
    {
        const word type =
            model_->template lookupOrDefault<word>("simulationType", "laminar");
        turbulent_ = type == "RAS" || type == "LES";
    }
}


Foam::tmp<Foam::scalarField> Foam::carrierTurbulence::nut
(
    const fvPatch& patch
) const
{
    if (!turbulent_)
    {
        return tmp<scalarField>::New(patch.size(), Zero);
    }
    return model_->nut(patch.index());
}
