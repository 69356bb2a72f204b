// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicReactingCloud
#include "basicReactingCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicReactingCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicReactingCloud);
makeParticleForceModelType(SlipSphereDragForce, basicReactingCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicReactingCloud);
