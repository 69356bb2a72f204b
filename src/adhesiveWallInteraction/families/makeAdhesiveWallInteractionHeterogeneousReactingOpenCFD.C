// adhesiveWallInteraction for the clouds of type basicHeterogeneousReactingCloud
#include "basicHeterogeneousReactingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicHeterogeneousReactingCloud);
