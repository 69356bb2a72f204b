// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicKinematicCollidingCloud
#include "basicKinematicCollidingCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionForce.H"
#include "NearWallDispersionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicCollidingCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicKinematicCollidingCloud);
makeParticleForceModelType(SlipSphereDragForce, basicKinematicCollidingCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicKinematicCollidingCloud);
makeParticleForceModelType(NearWallDispersionForce, basicKinematicCollidingCloud);
