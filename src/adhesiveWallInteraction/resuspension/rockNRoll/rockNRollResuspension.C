// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "rockNRollResuspension.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(rockNRollResuspension, 0);
    addToRunTimeSelectionTable(resuspensionModel, rockNRollResuspension, dictionary);
}


Foam::rockNRollResuspension::rockNRollResuspension(const input&)
:
    resuspensionModel(brachDunn::DepositResuspension::Kind::rockNRoll)
{}


Foam::wordList Foam::rockNRollResuspension::keywords(const input&) const
{
    return {"rmsRatio", "frequencyPlus"};
}


void Foam::rockNRollResuspension::readOwn(const input& in)
{
    law_.rmsRatio = checkedInput::readNumber(in.dict, "rmsRatio", law_.rmsRatio);
    law_.frequencyPlus =
        checkedInput::readNumber(in.dict, "frequencyPlus", law_.frequencyPlus);
}


// ************************************************************************* //
