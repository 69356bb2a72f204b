// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "wallInteractionCoeffs.H"
#include "checkedInput.H"
#include "releaseCompat.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Check the keywords first, then read capture
bool readRemoveCaptured(const dictionary& coeffs, const wordList& baseKeywords)
{
    // The model's keywords and the base classes' (writeToFile is both)
    wordList valid(wallInteractionCoeffs::keywords);
    for (const word& keyword : baseKeywords)
    {
        if (!valid.found(keyword))
        {
            valid.append(keyword);
        }
    }
    checkedInput::requireKnownKeywords
    (
        coeffs, valid, "adhesiveWallInteraction coefficients"
    );
    return
        checkedInput::readWord(coeffs, "capture", "stick", {"stick", "remove"})
     == "remove";
}


bool readOutputByInjectorId(const dictionary& coeffs)
{
    const bool byInjector =
        checkedInput::readSwitch(coeffs, "outputByInjectorId", false);
    if (byInjector && !compat::parcelsKnowTheirInjector)
    {
        checkedInput::fail
        (
            coeffs, "outputByInjectorId", "yes",
            std::string("not available on ") + compat::flavour()
          + "'s OpenFOAM, whose parcels do not carry their injector; use"
            " sizeClasses, or a cloud per injector"
        );
    }
    return byInjector;
}


//- Diameters between size classes: > 0, strictly increasing
scalarList readSizeClassEdges(const dictionary& coeffs)
{
    const scalarList edges(checkedInput::readNumbers(coeffs, "sizeClasses"));
    const entry* e = checkedInput::find(coeffs, "sizeClasses");
    if (e && edges.empty())
    {
        checkedInput::fail
        (
            coeffs, "sizeClasses", "()",
            "needs at least one diameter [m] between classes"
        );
    }
    forAll(edges, i)
    {
        if (!(edges[i] > 0) || (i && !(edges[i] > edges[i - 1])))
        {
            checkedInput::fail
            (
                coeffs, "sizeClasses", checkedInput::entryText(*e),
                "diameters [m] must be > 0 and increase strictly"
            );
        }
    }
    return edges;
}


//- The mesh patches whose impacts impacts.csv records: those recordPatches
//  names (names, regular expressions or groups, as the patch entries),
//  else every one
boolList readRecordedPatches
(
    const dictionary& coeffs,
    const UList<wallInteractionEntryList::patch>& patches,
    const label maxImpactRecords
)
{
    const std::string form = "a list of one or more patch names, regular"
        " expressions or groups such as (fibre \"(inlet|outlet)\")";
    boolList recorded(patches.size(), true);
    const entry* e = checkedInput::find(coeffs, "recordPatches");
    if (!e)
    {
        return recorded;
    }
    const List<keyType> keys
    (
        checkedInput::readKeys(coeffs, "recordPatches", form)
    );
    if (keys.empty())
    {
        checkedInput::fail
        (
            coeffs, "recordPatches", checkedInput::entryText(*e),
            "must be " + form
        );
    }
    if (maxImpactRecords == 0)
    {
        checkedInput::fail
        (
            coeffs, "recordPatches", checkedInput::entryText(*e),
            "selects the patches of impacts.csv, which is written only with"
            " maxImpactRecords > 0"
        );
    }
    recorded = false;
    for (const keyType& key : keys)
    {
        // Not the processor patches, which differ between processors
        bool matched = false;
        forAll(patches, patchi)
        {
            if
            (
                patches[patchi].type.compare(0, 9, "processor") != 0
             && wallInteractionEntryList::matches(key, patches[patchi])
            )
            {
                recorded[patchi] = matched = true;
            }
        }
        if (!matched)
        {
            checkedInput::fail
            (
                coeffs, "recordPatches", checkedInput::entryText(*e),
                "no patch matches " + std::string(key)
            );
        }
    }
    return recorded;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::wordList Foam::wallInteractionCoeffs::keywords
{
    "particle", "capture", "writeFields", "outputByInjectorId", "sizeClasses",
    "writeToFile", "maxImpactRecords", "recordPatches", "patches", "logTables",
    "extremeValues"
};


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::wallInteractionCoeffs::particleConstants&
Foam::wallInteractionCoeffs::particle
(
    const dictionary& coeffs,
    const std::optional<cloudParticle>& cloudParticle
)
{
    if (particle_)
    {
        return *particle_;
    }
    const dictionary* dict = checkedInput::findDictionary
    (
        coeffs, "particle", "{ E <Pa>; nu <->; }"
    );
    if (dict)
    {
        checkedInput::requireKnownKeywords
        (
            *dict, {"E", "nu"}, "the particle's elastic constants"
        );
        particle_ = particleConstants
        {
            readElasticMaterial(*dict, magnitudes_), "particle"
        };
    }
    else if (cloudParticle)
    {
        // Named as the cloud's constantProperties name them
        const dictionary& props = *cloudParticle->constantProperties;
        try
        {
            cloudParticle->material.check();
        }
        catch (const brachDunn::InputError& err)
        {
            checkedInput::fail
            (
                props,
                err.keyword() == "E" ? "youngsModulus" : "poissonsRatio",
                err.value(), err.requirement()
            );
        }
        magnitudes_.check
        (
            props, "youngsModulus", cloudParticle->material.E,
            brachDunn::magnitude::youngsModulus
        );
        particle_ = particleConstants
        {
            cloudParticle->material,
            "constantProperties youngsModulus, poissonsRatio"
        };
    }
    else
    {
        checkedInput::fail
        (
            coeffs, "particle", "missing",
            "an adhesive patch entry needs the particle's elastic constants,"
            " particle { E <Pa>; nu <->; } (colliding clouds take"
            " constantProperties youngsModulus and poissonsRatio)"
        );
    }
    return *particle_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallInteractionCoeffs::wallInteractionCoeffs
(
    const dictionary& coeffs,
    const UList<wallInteractionEntryList::patch>& patches,
    const std::optional<cloudParticle>& cloudParticle,
    const wordList& baseKeywords
)
:
    removeCaptured_(readRemoveCaptured(coeffs, baseKeywords)),
    writeFields_(checkedInput::readSwitch(coeffs, "writeFields", false)),
    writeToFile_(checkedInput::readSwitch(coeffs, "writeToFile", false)),
    outputByInjectorId_(readOutputByInjectorId(coeffs)),
    maxImpactRecords_(checkedInput::readCount(coeffs, "maxImpactRecords", 0)),
    recordedPatches_(readRecordedPatches(coeffs, patches, maxImpactRecords_)),
    sizeClassEdges_(readSizeClassEdges(coeffs)),
    logTables_(checkedInput::readSwitch(coeffs, "logTables", false)),
    magnitudes_
    {
        checkedInput::readSwitch(coeffs, "extremeValues", false)
    },
    particle_(),
    entries_
    (
        coeffs,
        patches,
        [&]{ return particle(coeffs, cloudParticle).material; },
        magnitudes_
    )
{
    // Size classes typed in um (2 for 2e-6) would put every parcel in one
    for (const scalar edge : sizeClassEdges_)
    {
        magnitudes_.checkMistake
        (
            coeffs, "sizeClasses", edge, brachDunn::magnitude::diameter
        );
    }

    // A particle given but not used is still checked
    if (checkedInput::find(coeffs, "particle"))
    {
        particle(coeffs, cloudParticle);
    }

    // Deposits that may leave again must stay in the cloud: known from the
    // coefficients alone (the tools see it too)
    for (const wallInteractionEntry& entry : entries_.entries())
    {
        if (removeCaptured_ && entry.resuspension())
        {
            checkedInput::fail
            (
                coeffs, "capture", "remove",
                "must be stick where an entry resuspends its deposits"
                " (entry " + std::string(entry.name()) + "): removed parcels"
                " cannot leave the wall again"
            );
        }
    }
}


void Foam::wallInteractionCoeffs::printSettings() const
{
    const std::vector<std::string>* warningLists[] =
    {
        &entries().warnings(), magnitudes().warnings.get()
    };
    for (const auto* warnings : warningLists)
    {
        for (const std::string& warning : *warnings)
        {
            WarningInFunction << warning.c_str() << endl;
        }
    }
    if (particle())
    {
        const particleConstants& constants = *particle();
        Info<< "    particle: E " << constants.material.E << " nu "
            << constants.material.nu << " (" << constants.origin.c_str()
            << ")" << nl;
    }
    for (const wallInteractionEntry& entry : entries().entries())
    {
        Info<< "    " << entry.describe().c_str() << nl;
    }
}


// ************************************************************************* //
