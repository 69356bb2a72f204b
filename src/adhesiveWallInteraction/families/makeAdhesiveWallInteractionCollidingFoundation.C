// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type collidingCloud
#include "collidingCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContactRefused.H"

makePatchInteractionModelType(AdhesiveWallInteraction, collidingCloud);
// Contact at the surface is not written for the Foundation's tracking:
// selected, it stops saying so
makeCloudFunctionObjectType(AdhesiveWallSurfaceContactRefused, collidingCloud);
