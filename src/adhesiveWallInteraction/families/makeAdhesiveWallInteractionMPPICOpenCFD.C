// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicKinematicMPPICCloud
#include "basicKinematicMPPICCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicMPPICCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicKinematicMPPICCloud);
