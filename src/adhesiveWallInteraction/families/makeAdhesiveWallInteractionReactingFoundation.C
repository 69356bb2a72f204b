// adhesiveWallInteraction for the clouds of type reactingCloud
#include "reactingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, reactingCloud);
