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


Foam::tmp<Foam::scalarField> Foam::carrierTurbulence::wallShearStress
(
    const fvPatch& patch,
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu
) const
{
    const label patchi = patch.index();
    const vectorField n(patch.nf());
    const vectorField gradU(U.boundaryField()[patchi].snGrad());
    const scalarField rhoC(rho.boundaryField()[patchi].patchInternalField());
    const scalarField muC(mu.boundaryField()[patchi].patchInternalField());
    const tmp<scalarField> nutW(nut(patch));
    auto tau = tmp<scalarField>::New(patch.size());
    forAll(n, facei)
    {
        const vector tangential =
            gradU[facei] - (n[facei] & gradU[facei])*n[facei];
        tau.ref()[facei] =
            (muC[facei] + rhoC[facei]*nutW()[facei])*mag(tangential);
    }
    return tau;
}
