// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicReactingMultiphaseCloud
#include "basicReactingMultiphaseCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "NearWallDispersionRefused.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicReactingMultiphaseCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicReactingMultiphaseCloud);
makeParticleForceModelType(SlipSphereDragForce, basicReactingMultiphaseCloud);
// nearWallDispersion is built for kinematic and colliding clouds: selected
// here, it stops naming the force and why (NearWallDispersionRefused.H)
makeParticleForceModelType(NearWallDispersionRefused, basicReactingMultiphaseCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicReactingMultiphaseCloud);
