// adhesiveWallInteraction for the clouds of type sprayCloud
#include "sprayCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, sprayCloud);
