// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicThermoCloud
#include "basicThermoCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicThermoCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicThermoCloud);
makeParticleForceModelType(SlipSphereDragForce, basicThermoCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicThermoCloud);
