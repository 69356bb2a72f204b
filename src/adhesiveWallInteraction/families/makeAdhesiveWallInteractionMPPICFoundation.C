// adhesiveWallInteraction for the clouds of type mppicCloud
#include "mppicCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, mppicCloud);
