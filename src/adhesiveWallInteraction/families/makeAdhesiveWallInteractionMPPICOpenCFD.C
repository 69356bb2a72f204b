// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type basicKinematicMPPICCloud
#include "basicKinematicMPPICCloud.H"
#include "AdhesiveWallInteraction.H"
#include "AdhesiveWallSurfaceContactRefused.H"
#include "SlipSphereDragForce.H"
#include "NearWallDispersionRefused.H"
#include "ExactBrownianMotionRefused.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicMPPICCloud);
// Contact at the surface is not for MPPIC clouds (two-way coupled by
// design, AdhesiveWallSurfaceContactRefused.H): selected there, it stops
// saying so
makeCloudFunctionObjectType(AdhesiveWallSurfaceContactRefused, basicKinematicMPPICCloud);
makeParticleForceModelType(SlipSphereDragForce, basicKinematicMPPICCloud);
// nearWallDispersion is built for kinematic and colliding clouds: selected
// here, it stops naming the force and why (NearWallDispersionRefused.H)
makeParticleForceModelType(NearWallDispersionRefused, basicKinematicMPPICCloud);
// exactBrownianMotion is not built for MPPIC clouds (their packing models
// move parcels outside the sub-step loop the exact step is written for):
// selected there, it stops saying so
makeParticleForceModelType(ExactBrownianMotionRefused, basicKinematicMPPICCloud);
