// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type reactingMultiphaseCloud
#include "reactingMultiphaseCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContactRefused.H"

makePatchInteractionModelType(AdhesiveWallInteraction, reactingMultiphaseCloud);
// Contact at the surface is not written for the Foundation's tracking:
// selected, it stops saying so
makeCloudFunctionObjectType(AdhesiveWallSurfaceContactRefused, reactingMultiphaseCloud);
