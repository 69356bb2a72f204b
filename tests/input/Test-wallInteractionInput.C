// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    Test-wallInteractionInput

Description
    The model's coefficients read from dictionaries as the solver reads
    them (wallInteractionCoeffs), with OpenFOAM's fatal errors thrown, so
    that each input is checked in milliseconds: every case either reads
    (valid input) or stops with a FatalIOError whose message holds the
    texts expected (the keyword, the value, the dictionary), and none ends
    in an abort.

    The cases edit a valid set of coefficients for a 1 mm box whose walls
    are floor, ceiling and sides (as tests/cases/base): an adhesive floor
    of the paper's Table 1 and rebound ceiling and sides.

Usage
    \b Test-wallInteractionInput

    Prints one line per case, "input: <case> ok", and exits 1 on any
    failure.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "releaseCompat.H"
#include "wallInteractionCoeffs.H"

#include <fenv.h>

#include <cmath>
#include <iostream>
#include <regex>
#include <string>
#include <utility>
#include <vector>

using namespace Foam;

namespace
{

//- One change of the valid coefficients
struct edit
{
    enum class kind { set, remove, removePatch, addPatch, replacePatches };
    kind what;
    std::string where;      //!< "" the coefficients, a patch entry's name,
                            //!< or a sub-dictionary path (floor/adhesion)
    std::string text;       //!< set: "keyword value"; remove: keyword;
                            //!< addPatch: the entry's dictionary
};

edit set(const std::string& where, const std::string& text)
{
    return {edit::kind::set, where, text};
}

edit remove(const std::string& where, const std::string& keyword)
{
    return {edit::kind::remove, where, keyword};
}


//- A case: edits of the valid coefficients, the mesh's patches, whether
//  the cloud is a colliding one, and the texts its error must hold (none:
//  the input is valid)
struct inputCase
{
    std::string name;
    std::vector<edit> edits;
    std::vector<std::string> expected;
    bool colliding = false;
    List<wallInteractionEntryList::patch> patches =
    {
        {"floor", "wall", {"wall"}, true, false},
        {"ceiling", "wall", {"wall"}, true, false},
        {"sides", "wall", {"wall"}, true, false}
    };
    //- A colliding cloud's youngsModulus [Pa]
    double collidingE = 1.2e9;
};


//- The coefficients under edit: all but the patches list, and the patch
//  entries in order (name as written, dictionary)
struct coefficients
{
    dictionary coeffs;
    std::vector<std::pair<std::string, dictionary>> patches;

    //- The patches entry as text, in place of the list (when set; empty:
    //  no patches entry)
    std::optional<std::string> patchesText;

    static dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    coefficients()
    :
        coeffs(parse("writeFields yes; writeToFile yes; maxImpactRecords 10;")),
        patches
        {
            {
                "floor",
                parse
                (
                    "type adhesive; E 3.2e11; nu 0.30;"
                    " restitution { type powerLaw; k 45.3; p 0.718; }"
                    " adhesion { type powerLaw; c 0.34; n 0.5; }"
                    " friction { type sticking; }"
                )
            },
            {"\"(ceiling|sides)\"", parse("type rebound; e 0.9; mu 0;")}
        }
    {
        coeffs.set(entry::New(IStringStream("particle { E 1.2e9; nu 0.33; }")()).ptr());
    }

    //- The dictionary an edit applies to
    dictionary& at(const std::string& where)
    {
        const auto slash = where.find('/');
        const std::string first = where.substr(0, slash);
        dictionary* dict = &coeffs;
        for (auto& [name, patch] : patches)
        {
            if (name == first) dict = &patch;
        }
        if (dict == &coeffs && !first.empty())
        {
            dict = &coeffs.subDict(first);
        }
        return
            slash == std::string::npos
          ? *dict : dict->subDict(where.substr(slash + 1));
    }

    void apply(const edit& e)
    {
        switch (e.what)
        {
            case edit::kind::set:
                at(e.where).set
                (
                    entry::New(IStringStream(e.text + ";")()).ptr()
                );
                break;
            case edit::kind::remove:
                at(e.where).remove(e.text);
                break;
            case edit::kind::removePatch:
                for (auto p = patches.begin(); p != patches.end(); ++p)
                {
                    if (p->first == e.where)
                    {
                        patches.erase(p);
                        break;
                    }
                }
                break;
            case edit::kind::addPatch:
                patches.push_back({e.where, parse(e.text)});
                break;
            case edit::kind::replacePatches:
                patchesText = e.text;
                break;
        }
    }

    //- The whole coefficients, named as in a case's cloud properties
    dictionary dictionaryOf() const
    {
        OStringStream os;
        coeffs.write(os, false);
        if (patchesText)
        {
            os << patchesText->c_str() << nl;
        }
        else
        {
            os << "patches" << nl << '(' << nl;
            for (const auto& [name, dict] : patches)
            {
                os << name.c_str();
                dict.write(os, true);
            }
            os << ");" << nl;
        }
        // Named as the solver names it, sub-dictionaries too
        IStringStream is(os.str());
        is.name() =
            "constant/kinematicCloudProperties.subModels"
            ".adhesiveWallInteractionCoeffs";
        dictionary dict(is);
        dict.name() = is.name();
        return dict;
    }
};


//- Hit every entry that has impacts with particles of a range of sizes,
//  speeds (up to the largest the core takes) and angles, floating-point
//  errors trapped (a trap ends the test): the coefficients a dictionary
//  passes must not overflow
void hitEveryEntry(const wallInteractionCoeffs& coeffs)
{
    using interaction = wallInteractionEntry::interaction;
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    const vector nw(0, 0, -1);
    for (const wallInteractionEntry& entry : coeffs.entries().entries())
    {
        if (entry.type() == interaction::none) continue;
        for (const scalar d : {1e-10, 1e-7, 4.9e-6, 1e-3, 10.0})
        {
            for (const scalar v : {1e-9, 1e-3, 1.0, 1e2, 1e4, 1e8})
            {
                for (const scalar angle : {0.0, 1.0, 1.5707})
                {
                    const vector U(v*std::sin(angle), 0, -v*std::cos(angle));
                    const wallImpact r = entry.impact(d, 1e5, U, nw);
                    if (!std::isfinite(magSqr(r.U)) || !std::isfinite(r.energyLoss))
                    {
                        FatalErrorInFunction
                            << "entry " << entry.name() << ": impact at d "
                            << d << " v " << v << " not finite"
                            << exit(FatalError);
                    }
                }
            }
        }
    }
    fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
}


//- Read the coefficients of a case; false, and the message, on an error
bool readCoefficients(const inputCase& c, std::string& message)
{
    coefficients k;
    for (const edit& e : c.edits)
    {
        k.apply(e);
    }
    // A colliding cloud's constantProperties, named as in a case
    dictionary constantProperties;
    constantProperties.name() =
        "constant/kinematicCloudProperties.constantProperties";
    constantProperties.add("youngsModulus", c.collidingE);
    constantProperties.add("poissonsRatio", 0.33);
    std::optional<wallInteractionCoeffs::cloudParticle> cloudParticle;
    if (c.colliding)
    {
        cloudParticle = wallInteractionCoeffs::cloudParticle
        {
            {c.collidingE, 0.33}, &constantProperties
        };
    }
    try
    {
        const compat::fatalErrorsThrow throwing;
        // As the solver: the base classes' keywords first
        const dictionary coeffsDict(k.dictionaryOf());
        dictionary subModels;
        subModels.add("adhesiveWallInteractionCoeffs", coeffsDict);
        checkedInput::baseKeywordsChecked
        (
            subModels, "adhesiveWallInteraction", compat::baseKeywords()
        );
        const wallInteractionCoeffs coeffs
        (
            coeffsDict, c.patches, cloudParticle, compat::baseKeywords()
        );
        hitEveryEntry(coeffs);
        return true;
    }
    catch (const Foam::error& err)
    {
        message = err.message();
        return false;
    }
    catch (const brachDunn::InputError& err)
    {
        message = std::string("an impact of valid coefficients refused: ")
          + err.what();
        return false;
    }
}


//- The box's patches with a symmetry patch, front
List<wallInteractionEntryList::patch> withSymmetry()
{
    return
    {
        {"floor", "wall", {"wall"}, true, false},
        {"ceiling", "wall", {"wall"}, true, false},
        {"sides", "wall", {"wall"}, true, false},
        {"front", "symmetry", {"symmetry"}, false, true}
    };
}


//- The cases: every keyword error, and valid inputs around them
std::vector<inputCase> cases()
{
    const std::string floorCoeffs =
        "constant/kinematicCloudProperties.subModels"
        ".adhesiveWallInteractionCoeffs.patches.floor";
    return
    {
        {"valid", {}, {}},
        {"validStickOnlyWithoutParticle",
            {remove("", "particle"), set("floor", "type stick")}, {}},
        {"validCollidingCloudWithoutParticle",
            {remove("", "particle")}, {}, true},
        {"validDefaults",
            {remove("", "writeFields"), remove("", "writeToFile"),
             remove("", "maxImpactRecords"), remove("floor", "friction")}, {}},
        {"validBaseClassKeywords", {set("", "U U"), set("", "defaultCoeffs no")}, {}},
        {"validSizeClasses", {set("", "sizeClasses (1e-6 2e-6 5e-6)")}, {}},
        {"validRecordPatches",
            {set("", "recordPatches (floor \"(ceil|sid).*\" wall)")}, {}},

        {"type", {set("floor", "type bouncy")},
            {"keyword 'type' = bouncy", "unknown patch interaction", floorCoeffs}},
        {"nu", {set("floor", "nu 0.7")},
            {"keyword 'nu' = 0.7", "must be in (-1, 0.5]", floorCoeffs}},
        {"E", {set("floor", "E -3e11")},
            {"keyword 'E' = -3e+11", "must be in [1, 1e+14]"}},
        {"restitutionType", {set("floor", "restitution { type bouncy; }")},
            {"keyword 'type' = bouncy", "unknown restitution law",
             "patches.floor.restitution"}},
        {"missingP", {set("floor", "restitution { type powerLaw; k 45.3; }")},
            {"keyword 'p' = missing"}},
        {"misspeltP", {set("floor", "restitution { type powerLaw; k 45.3; pp 0.7; }")},
            {"keyword 'p' = missing", "given instead: pp"}},
        {"R", {set("floor", "restitution { type constant; R 1.5; }")},
            {"keyword 'R' = 1.5", "must be in [0, 1]"}},
        {"gamma", {set("floor", "adhesion { type constant; gamma -1; }")},
            {"keyword 'gamma' = -1", "must be in [0, 1e+06]"}},
        {"mu", {set("floor", "friction { type coulomb; mu -0.2; }")},
            {"keyword 'mu' = -0.2", "must be >= 0"}},
        {"momentCoeff", {set("floor", "momentCoeff 2")},
            {"keyword 'momentCoeff' = 2", "must be in [-1, 1]"}},
        {"vanDerWaals", {set("floor", "adhesion { type vanDerWaals; f 0.1; }")},
            {"keyword 'h' = missing"}},
        {"frictionWord", {set("floor", "friction coulomb")},
            {"keyword 'friction' = coulomb", "must be a dictionary"}},
        {"misspelt", {set("floor", "momentCoef 0.5")},
            {"keyword 'momentCoef' = 0.5",
             "not a keyword of patch entries of type adhesive", floorCoeffs}},
        {"misplaced", {set("floor", "mu 0.3")},
            {"keyword 'mu' = 0.3",
             "not a keyword of patch entries of type adhesive"}},
        {"lawKeyword",
            {set("floor", "adhesion { type vanDerWaals; h 7.3e-19; Z 3e-10; f 0.1; }")},
            {"keyword 'Z' = 3e-10", "not a keyword of adhesion law vanDerWaals",
             "patches.floor.adhesion"}},
        {"stickingMu", {set("floor", "friction { type sticking; mu 0.3; }")},
            {"keyword 'mu' = 0.3", "not a keyword of friction law sticking"}},
        {"unmatched", {{edit::kind::removePatch, "\"(ceiling|sides)\"", ""}},
            {"no entry matches the patches", "ceiling", "sides"}},
        {"capture", {set("", "capture glue")},
            {"keyword 'capture' = glue", "valid values are stick, remove"}},
        {"particleNu", {set("", "particle { E 1.2e9; nu -1; }")},
            {"keyword 'nu' = -1", ".particle"}},
        {"particleWord", {set("", "particle 1.2e9")},
            {"keyword 'particle' = 1.2e+09", "must be a dictionary"}},
        {"particleRho", {set("", "particle { E 1.2e9; nu 0.33; rho 1350; }")},
            {"keyword 'rho' = 1350",
             "not a keyword of the particle's elastic constants"}},
        {"particleMissing", {remove("", "particle")},
            {"keyword 'particle' = missing",
             "needs the particle's elastic constants"}},
        {"modelKeyword", {set("", "writeToFiles yes")},
            {"keyword 'writeToFiles' = yes",
             "not a keyword of adhesiveWallInteraction coefficients",
             // writeToFile, a keyword of the model and of the base class,
             // listed once (v1912's base keywords follow the model's)
             "maxImpactRecords recordPatches patches logTables extremeValues U"
             " defaultCoeffs writePrecision useUserTime"}},
        {"recordPatchesUnmatched", {set("", "recordPatches (floor flor)")},
            {"keyword 'recordPatches' = (floor flor)", "no patch matches flor"}},
        {"recordPatchesWord", {set("", "recordPatches floor")},
            {"keyword 'recordPatches' = floor", "must be a list of one or more patch names"}},
        {"recordPatchesNumbers", {set("", "recordPatches (floor 2)")},
            {"keyword 'recordPatches' = (floor 2)", "must be a list of one or more patch names"}},
        {"validRecordPatchesSized", {set("", "recordPatches 2(floor sides)")}, {}},
        {"recordPatchesSize", {set("", "recordPatches 3(floor sides)")},
            {"keyword 'recordPatches' = 3 (floor sides)", "must be a list of one or more patch names"}},
        {"recordPatchesEmpty", {set("", "recordPatches ()")},
            {"keyword 'recordPatches' = ()", "must be a list of one or more patch names"}},
        {"recordPatchesWithoutRecords",
            {set("", "recordPatches (floor)"), remove("", "maxImpactRecords")},
            {"keyword 'recordPatches' = (floor)", "maxImpactRecords > 0"}},
        {"sizeClassesOrder", {set("", "sizeClasses (2e-6 1e-6)")},
            {"keyword 'sizeClasses' = (2e-06 1e-06)", "increase strictly"}},
        // Coefficients that used to overflow at the first impact
        {"powerLawP1100", {set("floor", "restitution { type powerLaw; k 45.3; p 1100; }")},
            {"keyword 'p' = 1100", "must be in [0, 10]"}},
        {"powerLawP1e300", {set("floor", "restitution { type powerLaw; k 45.3; p 1e300; }")},
            {"keyword 'p' = 1e+300"}},
        {"adhesionN1100", {set("floor", "adhesion { type powerLaw; c 0.34; n 1100; }")},
            {"keyword 'n' = 1100", "must be in [0, 10]"}},
        {"adhesionN1e300", {set("floor", "adhesion { type powerLaw; c 0.34; n 1e300; }")},
            {"keyword 'n' = 1e+300"}},
        {"yieldStress1e62", {set("floor", "restitution { type elasticPlastic; yieldStress 1e62; }")},
            {"keyword 'yieldStress' = 1e+62", "must be in (0, 1e+14]"}},
        {"yieldStress1e300", {set("floor", "restitution { type elasticPlastic; yieldStress 1e300; }")},
            {"keyword 'yieldStress' = 1e+300"}},
        {"vanDerWaalsHuge", {set("floor", "adhesion { type vanDerWaals; h 1e300; z 1e-100; f 1; }")},
            {"keyword 'h' = 1e+300", "must be in (0, 1e-14]"}},
        {"validAtTheLimits",
            {set("", "extremeValues yes"),
             set("floor", "restitution { type elasticPlastic; yieldStress 1e14; }"),
             set("floor", "adhesion { type powerLaw; c 1e6; n 10; }")}, {}},
        // Magnitudes that can only be unit mistakes (extremeValues: as given)
        {"youngsModulusInGPa", {set("floor", "E 320")},
            {"keyword 'E' = 320", "a Young's modulus in Pa",
             "did you mean 3.2e+11 (320 GPa)", floorCoeffs}},
        {"particleEInGPa", {set("particle", "E 70")},
            {"keyword 'E' = 70", "did you mean 7e+10 (70 GPa)", ".particle"}},
        {"gammaInMilli", {set("floor", "adhesion { type constant; gamma 50; }")},
            {"keyword 'gamma' = 50", "did you mean 0.05 (50 mJ/m^2)"}},
        {"powerLawCInMilli", {set("floor", "adhesion { type powerLaw; c 340; n 0.5; }")},
            {"keyword 'c' = 340", "did you mean 0.34 (340 mJ/m^2)"}},
        {"collidingYoungsModulusInGPa", {remove("", "particle")},
            {"keyword 'youngsModulus' = 60", "did you mean 6e+10 (60 GPa)",
             "constantProperties", "extremeValues yes in adhesiveWallInteractionCoeffs"},
            true,
            {
                {"floor", "wall", {"wall"}, true, false},
                {"ceiling", "wall", {"wall"}, true, false},
                {"sides", "wall", {"wall"}, true, false}
            },
            60},
        {"removedDepositsCannotResuspend",
            {set("", "capture remove"),
             set("floor", "resuspension { type rockNRoll; w 0.5; }")},
            {"keyword 'capture' = remove", "must be stick where an entry"
             " resuspends its deposits (entry floor)"}},
        {"sizeClassesInMicrometres", {set("", "sizeClasses (2 5)")},
            {"keyword 'sizeClasses' = 2", "did you mean 2e-06 (2 um)"}},
        {"validExtremeValues", {set("", "extremeValues yes"), set("floor", "E 320")}, {}},
        {"extremeValuesWord", {set("", "extremeValues maybe")},
            {"keyword 'extremeValues' = maybe", "must be yes or no"}},
        {"validLogTables", {set("", "logTables yes")}, {}},
        {"validPowerLawLimits",
            {set("floor", "restitution { type powerLaw; k 1e-3; p 10; }")}, {}},
        {"validVanDerWaalsLimits",
            {set("floor", "adhesion { type vanDerWaals; h 1e-14; z 1e-12; f 1; }")}, {}},

        // Values that used to abort, crash, or read in silence
        {"dictionaryForE", {set("floor", "E { a 1; }")},
            {"keyword 'E' = { ... }", "must be a number, not a dictionary"}},
        {"dictionaryForType", {set("floor", "type { a 1; }")},
            {"keyword 'type' = { ... }", "must be a word, not a dictionary"}},
        {"dictionaryForCapture", {set("", "capture { a 1; }")},
            {"keyword 'capture' = { ... }"}},
        {"dictionaryForWriteFields", {set("", "writeFields { a 1; }")},
            {"keyword 'writeFields' = { ... }", "must be yes or no"}},
        {"dictionaryForParticleNu", {set("particle", "nu { a 1; }")},
            {"keyword 'nu' = { ... }"}},
        {"dictionaryForReboundE", {set("\"(ceiling|sides)\"", "e { a 1; }")},
            {"keyword 'e' = { ... }"}},
        {"dictionaryForPatches",
            {{edit::kind::replacePatches, "", "patches { floor { type stick; } }"}},
            {"keyword 'patches' = { ... }", "must be a list"}},
        {"writeFields2", {set("", "writeFields 2")},
            {"keyword 'writeFields' = 2", "must be yes or no"}},
        {"outputByInjectorIdWord", {set("", "outputByInjectorId maybe")},
            {"keyword 'outputByInjectorId' = maybe"}},
        {"minusInfE", {set("floor", "E -inf")},
            {"keyword 'E' = -inf", "must be a finite number"}},
        // (OpenFOAM's own parser reads numbers below 1e-300 as 0)
        {"tinyE", {set("floor", "E 1e-299")},
            {"keyword 'E' = 1e-299", "must be in [1, 1e+14]"}},
        {"unusedBadParticle",
            {set("floor", "type stick"), set("", "particle { E -1; nu 0.9; }")},
            {"keyword 'E' = -1", ".particle"}},
        {"unusedParticleWord",
            {set("floor", "type stick"), set("", "particle foo")},
            {"keyword 'particle' = foo", "must be a dictionary"}},
        {"tableGarbage",
            {set("floor", "restitution { type table; values ((0 1) (10 x)); }")},
            {"keyword 'values' = ((0 1) (10 x))", "list of (speed value) pairs"}},
        {"validTable",
            {set("floor", "restitution { type table; values ((0 1) (10 0.9)); }")}, {}},

        // Base classes' keywords, checked before the base classes read them
        {"baseWriteToFileDictionary", {set("", "writeToFile { a 1; }")},
            {"keyword 'writeToFile' = { ... }"}},
        {"baseUDictionary", {set("", "U { a 1; }")},
            {"keyword 'U' = { ... }", "must be a word"}},

        // Constraint patches, opt-in (patchType)
        {"validSymmetryOptIn",
            {{edit::kind::addPatch, "front", "type stick; patchType symmetry;"}},
            {}, false, withSymmetry()},
        {"symmetryLeftToOpenFOAM", {}, {}, false, withSymmetry()},
        {"patchTypeWrong",
            {{edit::kind::addPatch, "front", "type stick; patchType cyclic;"}},
            {"keyword 'patchType' = cyclic",
             "valid values are symmetry, symmetryPlane, wedge"},
            false, withSymmetry()}
    };
}

//- Generated mutations of the valid coefficients: every keyword given a
//  wrong kind of value, a value out of any range, deleted or misspelt.
//  Each must read, or stop with a message naming a keyword and its value;
//  expected: the keyword and the value as the message shows it
struct mutation
{
    std::string name;
    edit change;
    std::string keyword;
    std::string shown;      //!< the value as messages show it
};

std::vector<mutation> mutations()
{
    const std::vector<std::pair<std::string, std::string>> sites
    {
        {"", "writeFields"}, {"", "writeToFile"}, {"", "maxImpactRecords"},
        {"", "capture"}, {"", "outputByInjectorId"}, {"", "sizeClasses"},
        {"", "recordPatches"},
        {"", "particle"}, {"", "U"}, {"", "defaultCoeffs"},
        {"particle", "E"}, {"particle", "nu"},
        {"floor", "type"}, {"floor", "E"}, {"floor", "nu"},
        {"floor", "momentCoeff"}, {"floor", "minReboundSpeed"},
        {"floor", "friction"}, {"floor", "restitution"}, {"floor", "adhesion"},
        {"floor", "patchType"},
        {"floor/restitution", "type"}, {"floor/restitution", "k"},
        {"floor/restitution", "p"},
        {"floor/adhesion", "type"}, {"floor/adhesion", "c"},
        {"floor/adhesion", "n"},
        {"floor/friction", "type"},
        {"\"(ceiling|sides)\"", "type"}, {"\"(ceiling|sides)\"", "e"},
        {"\"(ceiling|sides)\"", "mu"}
    };
    // (value as written, value as the messages show it)
    const std::vector<std::pair<std::string, std::string>> values
    {
        {"{ a 1; }", "{ ... }"}, {"foo", "foo"}, {"1 2", "1 2"},
        {"nan", "nan"}, {"-inf", "-inf"}, {"inf", "inf"},
        {"1e-299", "1e-299"}, {"1e300", "1e+300"}, {"-1", "-1"},
        {"0", "0"}, {"2", "2"}, {"0.5", "0.5"}, {"(1 2)", "(1 2)"},
        {"\"text\"", "\"text\""}, {"yes", "yes"}, {"1100", "1100"},
        {"1e62", "1e+62"}, {"-0.99", "-0.99"}
    };
    std::vector<mutation> all;
    for (const auto& [value, shown] : values)
    {
        all.push_back
        (
            {
                "patches = " + value,
                {edit::kind::replacePatches, "", "patches " + value + ";"},
                "patches", shown
            }
        );
    }
    all.push_back
    (
        {"patches deleted", {edit::kind::replacePatches, "", ""}, "patches", "missing"}
    );
    for (const auto& [where, keyword] : sites)
    {
        const std::string site = (where.empty() ? "" : where + "/") + keyword;
        for (const auto& [value, shown] : values)
        {
            all.push_back
            (
                {site + " = " + value, set(where, keyword + " " + value), keyword, shown}
            );
        }
        all.push_back({site + " deleted", remove(where, keyword), keyword, "missing"});
        all.push_back
        (
            {site + " misspelt", set(where, keyword + "x 1"), keyword + "x", "1"}
        );
    }
    return all;
}


//- Run the mutations; the number that failed. verbose: what each did
label fuzz(const bool verbose)
{
    label failed = 0, read = 0, named = 0, other = 0;
    for (const mutation& m : mutations())
    {
        inputCase c{m.name, {m.change}, {}};
        std::string message;
        if (readCoefficients(c, message))
        {
            ++read;
            if (verbose)
            {
                std::cout << "fuzz: " << m.name << ": read\n";
            }
            continue;
        }
        // The error of this keyword and value, or of another keyword the
        // change brought up (a type changed makes other keywords foreign),
        // always in the model's form: keyword 'K' = value: requirement
        const std::string exact =
            "keyword '" + m.keyword + "' = " + m.shown + ": ";
        const bool ours = std::regex_search
        (
            message, std::regex("keyword '[^']+' = [^\n]+: ")
        );
        if (message.find(exact) != std::string::npos)
        {
            ++named;
        }
        else if (ours)
        {
            ++other;
            if (verbose)
            {
                std::cout << "fuzz: " << m.name << ": " << message << '\n';
            }
        }
        else
        {
            ++failed;
            std::cout << "fuzz: " << m.name << " FAILED: no keyword and value"
                << " in the message\n    message: " << message << '\n';
        }
    }
    std::cout << "fuzz: " << mutations().size() << " mutations: " << read
        << " read, " << named << " stopped naming the keyword changed, "
        << other << " stopped naming another keyword with its value, "
        << failed << " failed\n";
    return failed;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    compat::noBanner();
    argList::addBoolOption("verbose", "what each generated mutation did");
    #include "setRootCase.H"

    label failed = 0;
    for (const inputCase& c : cases())
    {
        std::string message;
        const bool read = readCoefficients(c, message);
        std::string problem;
        if (c.expected.empty() && !read)
        {
            problem = "valid input refused";
        }
        else if (!c.expected.empty() && read)
        {
            problem = "bad input accepted";
        }
        for (const std::string& text : c.expected)
        {
            if (!read && message.find(text) == std::string::npos)
            {
                problem += "'" + text + "' not in the message; ";
            }
        }
        if (problem.empty())
        {
            std::cout << "input: " << c.name << " ok\n";
        }
        else
        {
            ++failed;
            std::cout << "input: " << c.name << " FAILED: " << problem
                << "\n    message: " << message << '\n';
        }
    }
    std::cout << "input: " << failed << " failed\n";
    failed += fuzz(compat::optionFound(args, "verbose"));
    if (failed)
    {
        // Returning 1 is not enough: the argList ends the process with
        // status 0 when main returns (OpenFOAM v1912: UPstream::exit(0))
        FatalErrorInFunction
            << failed << " input cases or mutations failed"
            << exit(FatalError);
    }
    return 0;
}
