// adhesiveWallInteraction for the clouds of type basicReactingCloud
#include "basicReactingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicReactingCloud);
