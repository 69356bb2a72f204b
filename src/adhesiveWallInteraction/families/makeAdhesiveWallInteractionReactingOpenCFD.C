// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicReactingCloud
#include "basicReactingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicReactingCloud);
