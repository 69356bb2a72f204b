// adhesiveWallInteraction for the clouds of type basicSprayCloud
// (lagrangian/spray: sprayFoam and its relatives)
#include "basicSprayCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicSprayCloud);
