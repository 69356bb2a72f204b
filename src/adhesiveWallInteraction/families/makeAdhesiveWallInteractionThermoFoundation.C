// adhesiveWallInteraction for the clouds of type thermoCloud
#include "thermoCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, thermoCloud);
