// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicThermoCloud
#include "basicThermoCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicThermoCloud);
