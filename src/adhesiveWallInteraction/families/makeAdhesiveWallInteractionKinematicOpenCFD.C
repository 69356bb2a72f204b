// adhesiveWallInteraction for the clouds of type basicKinematicCloud
#include "basicKinematicCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicCloud);
