// adhesiveWallInteraction for the clouds of type basicKinematicMPPICCloud
#include "basicKinematicMPPICCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicMPPICCloud);
