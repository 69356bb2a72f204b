// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type collidingCloud
#include "collidingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, collidingCloud);
