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

#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace Foam;

namespace
{

//- One change of the valid coefficients
struct edit
{
    enum class kind { set, remove, removePatch, addPatch };
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
};


//- The coefficients under edit: all but the patches list, and the patch
//  entries in order (name as written, dictionary)
struct coefficients
{
    dictionary coeffs;
    std::vector<std::pair<std::string, dictionary>> patches;

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
        }
    }

    //- The whole coefficients, named as in a case's cloud properties
    dictionary dictionaryOf() const
    {
        OStringStream os;
        coeffs.write(os, false);
        os << "patches" << nl << '(' << nl;
        for (const auto& [name, dict] : patches)
        {
            os << name.c_str();
            dict.write(os, true);
        }
        os << ");" << nl;
        dictionary dict(parse(os.str()));
        dict.name() =
            "constant/kinematicCloudProperties.subModels"
            ".adhesiveWallInteractionCoeffs";
        return dict;
    }
};


//- Read the coefficients of a case; false, and the message, on an error
bool readCoefficients(const inputCase& c, std::string& message)
{
    coefficients k;
    for (const edit& e : c.edits)
    {
        k.apply(e);
    }
    std::optional<brachDunn::ElasticMaterial> cloudParticle;
    if (c.colliding)
    {
        cloudParticle = brachDunn::ElasticMaterial{1.2e9, 0.33};
    }
    try
    {
        const compat::fatalErrorsThrow throwing;
        const wallInteractionCoeffs coeffs
        (
            k.dictionaryOf(), c.patches, cloudParticle, compat::baseKeywords()
        );
        return true;
    }
    catch (const Foam::error& err)
    {
        message = err.message();
        return false;
    }
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

        {"type", {set("floor", "type bouncy")},
            {"keyword 'type' = bouncy", "unknown patch interaction", floorCoeffs}},
        {"nu", {set("floor", "nu 0.7")},
            {"keyword 'nu' = 0.7", "must be in (-1, 0.5]", floorCoeffs}},
        {"E", {set("floor", "E -3e11")},
            {"keyword 'E' = -3e+11", "must be > 0"}},
        {"restitutionType", {set("floor", "restitution { type bouncy; }")},
            {"keyword 'type' = bouncy", "unknown restitution law",
             "patches.floor.restitution"}},
        {"missingP", {set("floor", "restitution { type powerLaw; k 45.3; }")},
            {"keyword 'p' = missing"}},
        {"R", {set("floor", "restitution { type constant; R 1.5; }")},
            {"keyword 'R' = 1.5", "must be in [0, 1]"}},
        {"gamma", {set("floor", "adhesion { type constant; gamma -1; }")},
            {"keyword 'gamma' = -1", "must be >= 0"}},
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
             "not a keyword of adhesiveWallInteraction coefficients"}},
        {"sizeClassesOrder", {set("", "sizeClasses (2e-6 1e-6)")},
            {"keyword 'sizeClasses' = (2e-06 1e-06)", "increase strictly"}}
    };
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    compat::noBanner();
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
    return failed ? 1 : 0;
}
