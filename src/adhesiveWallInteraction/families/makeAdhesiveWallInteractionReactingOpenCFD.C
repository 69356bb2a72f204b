// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicReactingCloud
#include "basicReactingCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "NearWallDispersionRefused.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicReactingCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicReactingCloud);
makeParticleForceModelType(SlipSphereDragForce, basicReactingCloud);
// nearWallDispersion is built for kinematic and colliding clouds: selected
// here, it stops naming the force and why (NearWallDispersionRefused.H)
makeParticleForceModelType(NearWallDispersionRefused, basicReactingCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicReactingCloud);
