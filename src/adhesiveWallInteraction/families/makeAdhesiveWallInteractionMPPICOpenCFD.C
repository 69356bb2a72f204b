// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicKinematicMPPICCloud
#include "basicKinematicMPPICCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicMPPICCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicKinematicMPPICCloud);
makeParticleForceModelType(SlipSphereDragForce, basicKinematicMPPICCloud);
// exactBrownianMotion is not registered for MPPIC clouds: their packing
// models move parcels outside the sub-step loop the exact step is written for
