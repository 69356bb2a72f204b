// adhesiveWallInteraction for the clouds of type basicKinematicCollidingCloud
#include "basicKinematicCollidingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicKinematicCollidingCloud);
