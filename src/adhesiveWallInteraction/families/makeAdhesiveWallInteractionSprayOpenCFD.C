// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicSprayCloud
// (lagrangian/spray: sprayFoam and its relatives)
#include "basicSprayCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "NearWallDispersionRefused.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicSprayCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicSprayCloud);
makeParticleForceModelType(SlipSphereDragForce, basicSprayCloud);
// nearWallDispersion is built for kinematic and colliding clouds: selected
// here, it stops naming the force and why (NearWallDispersionRefused.H)
makeParticleForceModelType(NearWallDispersionRefused, basicSprayCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicSprayCloud);
