// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// adhesiveWallInteraction for the clouds of type reactingCloud
#include "reactingCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, reactingCloud);
