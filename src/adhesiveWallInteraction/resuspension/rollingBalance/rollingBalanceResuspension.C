// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "rollingBalanceResuspension.H"
#include "addToRunTimeSelectionTable.H"
#include "wallInteractionEntry.H"

namespace Foam
{
    defineTypeNameAndDebug(rollingBalanceResuspension, 0);
    addToRunTimeSelectionTable
    (
        resuspensionModel,
        rollingBalanceResuspension,
        dictionary
    );
}


Foam::rollingBalanceResuspension::rollingBalanceResuspension(const input&)
:
    resuspensionModel(brachDunn::DepositResuspension::Kind::rollingBalance)
{}


Foam::wordList Foam::rollingBalanceResuspension::keywords
(
    const input& in
) const
{
    return in.wall ? wordList() : wordList{"E", "nu"};
}


std::string Foam::rollingBalanceResuspension::keywordNote
(
    const input& in
) const
{
    return in.wall ? " in an adhesive entry (its E and nu are the wall's)" : "";
}


void Foam::rollingBalanceResuspension::readOwn(const input& in)
{
    const brachDunn::ElasticMaterial wall =
        in.wall ? *in.wall : readElasticMaterial(in.dict, in.magnitudes);
    law_.contactModulus = brachDunn::contactModulus(in.particle(), wall);
}


// ************************************************************************* //
