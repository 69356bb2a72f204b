// adhesiveWallInteraction for the clouds of type basicReactingMultiphaseCloud
#include "basicReactingMultiphaseCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicReactingMultiphaseCloud);
