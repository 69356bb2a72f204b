// adhesiveWallInteraction for the clouds of type reactingMultiphaseCloud
#include "reactingMultiphaseCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, reactingMultiphaseCloud);
