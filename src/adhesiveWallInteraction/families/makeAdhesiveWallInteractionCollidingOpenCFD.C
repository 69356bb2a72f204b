// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicKinematicCollidingCloud
#include "basicKinematicCollidingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicCollidingCloud);
