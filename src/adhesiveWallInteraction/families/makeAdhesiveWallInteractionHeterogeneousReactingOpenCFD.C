// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicHeterogeneousReactingCloud
#include "basicHeterogeneousReactingCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicHeterogeneousReactingCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicHeterogeneousReactingCloud);
makeParticleForceModelType(SlipSphereDragForce, basicHeterogeneousReactingCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicHeterogeneousReactingCloud);
