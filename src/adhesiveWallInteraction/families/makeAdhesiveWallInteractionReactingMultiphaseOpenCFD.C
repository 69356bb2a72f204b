// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicReactingMultiphaseCloud
#include "basicReactingMultiphaseCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicReactingMultiphaseCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicReactingMultiphaseCloud);
makeParticleForceModelType(SlipSphereDragForce, basicReactingMultiphaseCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicReactingMultiphaseCloud);
