// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicKinematicMPPICCloud
#include "basicKinematicMPPICCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionRefused.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicMPPICCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicKinematicMPPICCloud);
makeParticleForceModelType(SlipSphereDragForce, basicKinematicMPPICCloud);
// exactBrownianMotion is not built for MPPIC clouds (their packing models
// move parcels outside the sub-step loop the exact step is written for):
// selected there, it stops saying so
makeParticleForceModelType(ExactBrownianMotionRefused, basicKinematicMPPICCloud);
