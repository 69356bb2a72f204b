// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicThermoCloud
#include "basicThermoCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "NearWallDispersionRefused.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicThermoCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicThermoCloud);
makeParticleForceModelType(SlipSphereDragForce, basicThermoCloud);
// nearWallDispersion is built for kinematic and colliding clouds: selected
// here, it stops naming the force and why (NearWallDispersionRefused.H)
makeParticleForceModelType(NearWallDispersionRefused, basicThermoCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicThermoCloud);
