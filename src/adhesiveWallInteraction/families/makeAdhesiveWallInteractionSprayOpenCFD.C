// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicSprayCloud
// (lagrangian/spray: sprayFoam and its relatives)
#include "basicSprayCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContact.H"
#include "SlipSphereDragForce.H"
#include "ExactBrownianMotionForce.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicSprayCloud);
makeCloudFunctionObjectType(AdhesiveWallSurfaceContact, basicSprayCloud);
makeParticleForceModelType(SlipSphereDragForce, basicSprayCloud);
makeParticleForceModelType(ExactBrownianMotionForce, basicSprayCloud);
