// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicKinematicCloud
#include "basicKinematicCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionForce.H"
#include "NearWallDispersionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicKinematicCloud);
makeParticleForceModelType(SlipSphereDragForce, basicKinematicCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicKinematicCloud);
makeParticleForceModelType(NearWallDispersionForce, basicKinematicCloud);
