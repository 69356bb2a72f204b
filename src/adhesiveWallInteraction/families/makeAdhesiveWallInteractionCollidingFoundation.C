// adhesiveWallInteraction for the clouds of type collidingCloud
#include "collidingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, collidingCloud);
