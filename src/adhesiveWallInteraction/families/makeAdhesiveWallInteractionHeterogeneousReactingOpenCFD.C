// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicHeterogeneousReactingCloud
#include "basicHeterogeneousReactingCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "NearWallDispersionRefused.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicHeterogeneousReactingCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicHeterogeneousReactingCloud);
makeParticleForceModelType(SlipSphereDragForce, basicHeterogeneousReactingCloud);
// nearWallDispersion is built for kinematic and colliding clouds: selected
// here, it stops naming the force and why (NearWallDispersionRefused.H)
makeParticleForceModelType(NearWallDispersionRefused, basicHeterogeneousReactingCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicHeterogeneousReactingCloud);
