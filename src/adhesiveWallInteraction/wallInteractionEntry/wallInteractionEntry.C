#include "wallInteractionEntry.H"
#include "Tuple2.H"
#include "IOstreams.H"
#include "OStringStream.H"

#include <sstream>

// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- An entry's value as one line of text, for messages
std::string entryText(const entry& e)
{
    if (e.isDict())
    {
        return "{ ... }";
    }
    OStringStream os;
    const ITstream& tokens = e.stream();
    forAll(tokens, i)
    {
        // Numbers as the core's messages write them, at any writePrecision
        os << (i ? " " : "");
        if (tokens[i].isNumber())
        {
            os << brachDunn::toText(tokens[i].number()).c_str();
        }
        else
        {
            os << tokens[i];
        }
    }
    return os.str();
}


//- A law's keywords read from its OpenFOAM sub-dictionary
class dictionaryParameters
:
    public brachDunn::Parameters
{
    const dictionary& dict_;

public:

    explicit dictionaryParameters(const dictionary& dict) : dict_(dict) {}

    std::vector<std::pair<std::string, std::string>> given() const override
    {
        std::vector<std::pair<std::string, std::string>> all;
        for (const entry& e : dict_)
        {
            all.emplace_back(e.keyword(), entryText(e));
        }
        return all;
    }

protected:

    std::optional<double> lookup(const std::string& keyword) const override
    {
        if (!dict_.found(keyword, keyType::LITERAL)) return std::nullopt;
        return dict_.get<scalar>(keyword, keyType::LITERAL);
    }

    std::optional<brachDunn::Table> lookupTable
    (
        const std::string& keyword
    ) const override
    {
        if (!dict_.found(keyword, keyType::LITERAL)) return std::nullopt;
        const List<Tuple2<scalar, scalar>> pairs
        (
            dict_.get<List<Tuple2<scalar, scalar>>>(keyword, keyType::LITERAL)
        );
        brachDunn::Table table;
        for (const auto& pair : pairs)
        {
            table.push_back({pair.first(), pair.second()});
        }
        return table;
    }
};


//- The sub-dictionary under keyword, or nullptr when absent; an entry that
//  is not a dictionary is an error showing its value and the form expected
const dictionary* findSubDict
(
    const dictionary& dict,
    const word& keyword,
    const char* form
)
{
    const entry* found = dict.findEntry(keyword, keyType::LITERAL);
    if (found && !found->isDict())
    {
        FatalIOErrorInFunction(dict)
            << "In dictionary " << dict.name() << ": keyword '" << keyword
            << "' = " << entryText(*found).c_str() << ": must be a dictionary, "
            << keyword << ' ' << form << nl << exit(FatalIOError);
    }
    return found ? &found->dict() : nullptr;
}


//- The sub-dictionary of a law, named by its full scope for messages;
//  a missing one is an error naming the entry
dictionary lawDict(const dictionary& dict, const word& keyword)
{
    const char* form = "{ type ...; ... }";
    const dictionary* found = findSubDict(dict, keyword, form);
    if (!found)
    {
        FatalIOErrorInFunction(dict)
            << "In dictionary " << dict.name() << ": keyword '" << keyword
            << "' is missing; an adhesive patch needs "
            << keyword << ' ' << form << nl << exit(FatalIOError);
    }
    dictionary sub(*found);
    sub.name() = dict.name() + "." + keyword;
    return sub;
}


//- Build a law by its type name from its sub-dictionary
template<class Law>
Law readLaw(const dictionary& dict, const word& keyword)
{
    const dictionary sub(lawDict(dict, keyword));
    const word type(sub.get<word>("type"));
    return checkedCoreCall
    (
        sub,
        [&]{ return Law::select(type, dictionaryParameters(sub)); }
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::wordList Foam::wallInteractionEntry::interactionNames
{
    "adhesive", "rebound", "stick", "escape", "none"
};


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::requireKnownKeywords
(
    const dictionary& dict,
    const wordList& valid,
    const string& what
)
{
    for (const entry& e : dict)
    {
        if (!valid.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "In dictionary " << dict.name() << ": keyword '"
                << e.keyword() << "' = " << entryText(e).c_str()
                << ": not a keyword of " << what.c_str() << "; valid keywords:";
            for (const word& keyword : valid)
            {
                FatalIOError << ' ' << keyword;
            }
            FatalIOError << nl << exit(FatalIOError);
        }
    }
}


brachDunn::ElasticMaterial Foam::readElasticMaterial(const dictionary& dict)
{
    const brachDunn::ElasticMaterial material
    {
        dict.get<scalar>("E"),
        dict.get<scalar>("nu")
    };
    checkedCoreCall(dict, [&]{ material.check(); });
    return material;
}


const Foam::dictionary* Foam::findParticleDict(const dictionary& coeffs)
{
    const dictionary* found =
        findSubDict(coeffs, "particle", "{ E <Pa>; nu <->; }");
    if (found)
    {
        requireKnownKeywords
        (
            *found, {"E", "nu"}, "the particle's elastic constants"
        );
    }
    return found;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallInteractionEntry::wallInteractionEntry
(
    const keyType& name,
    const dictionary& dict,
    const brachDunn::ElasticMaterial& particleMaterial
)
:
    name_(name),
    type_(interaction::none),
    e_(1),
    mu_(0)
{
    const word typeName(dict.get<word>("type"));
    const label typeIndex = interactionNames.find(typeName);
    if (typeIndex < 0)
    {
        FatalIOErrorInFunction(dict)
            << "In dictionary " << dict.name() << ": keyword 'type' = "
            << typeName << ": unknown patch interaction; valid types:";
        for (const word& name : interactionNames)
        {
            FatalIOError << ' ' << name;
        }
        FatalIOError << nl << exit(FatalIOError);
    }
    type_ = static_cast<interaction>(typeIndex);

    // The entries with coefficients take only their own keywords, so that a
    // misspelt one is not ignored; stick, escape and none read nothing, and
    // may keep an adhesive entry's coefficients while cases are compared
    if (type_ == interaction::rebound)
    {
        requireKnownKeywords
        (
            dict, {"type", "e", "mu"}, "patch entries of type rebound"
        );

        // As standardWallInteraction: e in [0, 1], mu a loss fraction in [0, 1]
        e_ = dict.getOrDefault<scalar>("e", 1);
        mu_ = dict.getOrDefault<scalar>("mu", 0);
        checkedCoreCall(dict, [&]
        {
            brachDunn::requireInRange("e", e_, 0, 1);
            brachDunn::requireInRange("mu", mu_, 0, 1);
        });
    }
    else if (type_ == interaction::adhesive)
    {
        requireKnownKeywords
        (
            dict,
            {
                "type", "E", "nu", "restitution", "adhesion", "friction",
                "momentCoeff", "minReboundSpeed"
            },
            "patch entries of type adhesive"
        );

        const brachDunn::ElasticMaterial wall = readElasticMaterial(dict);
        const auto restitution =
            readLaw<brachDunn::RestitutionLaw>(dict, "restitution");
        const auto adhesion = readLaw<brachDunn::AdhesionLaw>(dict, "adhesion");
        // Sticking when absent; present, it must be a law's dictionary
        const auto friction =
            dict.found("friction", keyType::LITERAL)
          ? readLaw<brachDunn::FrictionLaw>(dict, "friction")
          : brachDunn::FrictionLaw::sticking();
        const scalar momentCoeff = dict.getOrDefault<scalar>("momentCoeff", -1);
        const scalar minReboundSpeed = dict.getOrDefault<scalar>
        (
            "minReboundSpeed", brachDunn::ImpactModel::defaultMinReboundSpeed
        );
        model_.emplace
        (
            checkedCoreCall(dict, [&]
            {
                return brachDunn::ImpactModel
                (
                    particleMaterial, wall, restitution, adhesion, friction,
                    momentCoeff, minReboundSpeed
                );
            })
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::wallInteractionEntry::describe() const
{
    std::ostringstream os;
    os << name_.c_str() << ": " << typeName().c_str();
    if (type_ == interaction::rebound)
    {
        os << " (e " << e_ << ", mu " << mu_ << ")";
    }
    else if (type_ == interaction::adhesive)
    {
        const brachDunn::ImpactModel& m = *model_;
        os  << " (wall E " << m.wallMaterial().E
            << " nu " << m.wallMaterial().nu
            << "; restitution { " << m.restitution().describe()
            << " } adhesion { " << m.adhesion().describe()
            << " } friction { " << m.friction().describe()
            << " } momentCoeff " << m.momentCoeff()
            << " minReboundSpeed " << m.minReboundSpeed() << ")";
    }
    return os.str();
}
