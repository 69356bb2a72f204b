// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "wallInteractionEntry.H"
#include "checkedInput.H"

#include <algorithm>
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

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
            all.emplace_back(e.keyword(), checkedInput::entryText(e));
        }
        return all;
    }

protected:

    std::optional<double> lookup(const std::string& keyword) const override
    {
        if (!checkedInput::find(dict_, keyword)) return std::nullopt;
        return checkedInput::readNumber(dict_, keyword);
    }

    std::optional<brachDunn::Table> lookupTable
    (
        const std::string& keyword
    ) const override
    {
        const entry* e = checkedInput::find(dict_, keyword);
        if (!e) return std::nullopt;
        const std::string form =
            "must be a list of (speed value) pairs such as ((0 1) (10 0.9))";
        if (e->isDict())
        {
            checkedInput::fail(dict_, keyword, "{ ... }", form);
        }

        // ((s v) (s v) ...), read token by token: anything else is an error
        const ITstream& tokens = e->stream();
        const auto punctuation = [&](const label i, const char c)
        {
            return
                i < tokens.size() && tokens[i].isPunctuation()
             && tokens[i].pToken() == c;
        };
        const auto number = [&](const label i)
        {
            return
                i < tokens.size() && tokens[i].isNumber()
             && std::isfinite(tokens[i].number());
        };
        brachDunn::Table table;
        label i = checkedInput::listStart(tokens);
        bool good = i >= 0;
        for (++i; good && !punctuation(i, token::END_LIST); i += 4)
        {
            good =
                punctuation(i, token::BEGIN_LIST) && number(i + 1)
             && number(i + 2) && punctuation(i + 3, token::END_LIST);
            if (good)
            {
                table.push_back({tokens[i + 1].number(), tokens[i + 2].number()});
            }
        }
        if (!good || i + 1 != tokens.size())
        {
            checkedInput::fail(dict_, keyword, checkedInput::entryText(*e), form);
        }
        return table;
    }
};


//- Build a law by its type name from its sub-dictionary
template<class Law>
Law readLaw(const dictionary& dict, const word& keyword)
{
    const dictionary sub
    (
        checkedInput::subDictionary
        (
            dict, keyword, "{ type ...; ... }", "an adhesive patch entry"
        )
    );
    const word type(checkedInput::readWord(sub, "type"));
    return checkedInput::coreCall
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


const Foam::wordList Foam::wallInteractionEntry::constraintPatchTypes
{
    "symmetry", "symmetryPlane", "wedge"
};


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

brachDunn::ElasticMaterial Foam::readElasticMaterial
(
    const dictionary& dict,
    const checkedInput::magnitudes& magnitudes
)
{
    const brachDunn::ElasticMaterial material
    {
        checkedInput::readNumber(dict, "E"),
        checkedInput::readNumber(dict, "nu")
    };
    checkedInput::coreCall(dict, [&]{ material.check(); });
    magnitudes.check
    (
        dict, "E", material.E, brachDunn::magnitude::youngsModulus
    );
    return material;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallInteractionEntry::wallInteractionEntry
(
    const keyType& name,
    const dictionary& dict,
    const particleMaterial& particle,
    const checkedInput::magnitudes& magnitudes
)
:
    name_(name),
    type_(readInteraction(dict)),
    patchType_
    (
        // Constraint patches of this type are the entry's too (opt-in)
        checkedInput::readWord
        (
            dict, "patchType", word::null, constraintPatchTypes
        )
    ),
    e_(1),
    mu_(0)
{
    // The entries with coefficients take only their own keywords, so that a
    // misspelt one is not ignored; stick (but its resuspension), escape and
    // none read nothing, and may keep an adhesive or rebound entry's
    // coefficients while cases are compared
    if (type_ == interaction::rebound)
    {
        readRebound(dict);
    }
    else if (type_ == interaction::adhesive)
    {
        readAdhesive(dict, particle, magnitudes);
    }
    else
    {
        // Another type's coefficients may stay; any other keyword (a
        // misspelt resuspension) is an error
        wordList known
        {
            "type", "patchType", "e", "mu", "E", "nu", "restitution",
            "adhesion", "friction", "momentCoeff", "minReboundSpeed"
        };
        if (type_ == interaction::stick)
        {
            known.append("resuspension");
        }
        checkedInput::requireKnownKeywords
        (
            dict, known,
            "patch entries of type " + typeName()
          + " (which may keep the keywords of other types)"
        );
        if (type_ == interaction::stick)
        {
            resuspension_ =
                readResuspension(dict, std::nullopt, particle, magnitudes);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::wallInteractionEntry::interaction
Foam::wallInteractionEntry::readInteraction(const dictionary& dict)
{
    const word typeName(checkedInput::readWord(dict, "type"));
    const auto found =
        std::find(interactionNames.begin(), interactionNames.end(), typeName);
    if (found == interactionNames.end())
    {
        std::string names;
        for (const word& name : interactionNames)
        {
            names += ' ' + name;
        }
        checkedInput::fail
        (
            dict, "type", typeName, "unknown patch interaction; valid types:"
          + names
        );
    }
    return static_cast<interaction>(found - interactionNames.begin());
}


void Foam::wallInteractionEntry::readRebound(const dictionary& dict)
{
    checkedInput::requireKnownKeywords
    (
        dict, {"type", "patchType", "e", "mu"}, "patch entries of type rebound"
    );

    // As standardWallInteraction: e in [0, 1], mu a loss fraction in [0, 1]
    e_ = checkedInput::readNumber(dict, "e", 1);
    mu_ = checkedInput::readNumber(dict, "mu", 0);
    checkedInput::coreCall(dict, [&]
    {
        brachDunn::requireInRange("e", e_, 0, 1);
        brachDunn::requireInRange("mu", mu_, 0, 1);
    });
}


void Foam::wallInteractionEntry::readAdhesive
(
    const dictionary& dict,
    const particleMaterial& particle,
    const checkedInput::magnitudes& magnitudes
)
{
    checkedInput::requireKnownKeywords
    (
        dict,
        {
            "type", "patchType", "E", "nu", "restitution", "adhesion",
            "friction", "momentCoeff", "minReboundSpeed", "resuspension"
        },
        "patch entries of type adhesive"
    );

    const brachDunn::ElasticMaterial wall = readElasticMaterial(dict, magnitudes);
    const auto restitution =
        readLaw<brachDunn::RestitutionLaw>(dict, "restitution");
    const auto adhesion = readLaw<brachDunn::AdhesionLaw>(dict, "adhesion");
    // A surface energy, or the power law's at 1 m/s, typed in mJ/m^2
    if (const auto* law = adhesion.as<brachDunn::adhesion::Constant>())
    {
        magnitudes.check
        (
            dict.subDict("adhesion"), "gamma", law->gamma,
            brachDunn::magnitude::surfaceEnergy
        );
    }
    if (const auto* law = adhesion.as<brachDunn::adhesion::PowerLaw>())
    {
        magnitudes.check
        (
            dict.subDict("adhesion"), "c", law->c,
            brachDunn::magnitude::surfaceEnergy
        );
    }
    // Sticking when absent; present, it must be a law's dictionary
    const auto friction =
        checkedInput::find(dict, "friction")
      ? readLaw<brachDunn::FrictionLaw>(dict, "friction")
      : brachDunn::FrictionLaw::sticking();
    const scalar momentCoeff =
        checkedInput::readNumber(dict, "momentCoeff", -1);
    const scalar minReboundSpeed = checkedInput::readNumber
    (
        dict, "minReboundSpeed",
        brachDunn::ImpactModel::defaultMinReboundSpeed
    );
    resuspension_ = readResuspension(dict, wall, particle, magnitudes);
    const brachDunn::ElasticMaterial particleConstants = particle();
    model_.emplace
    (
        checkedInput::coreCall(dict, [&]
        {
            return brachDunn::ImpactModel
            (
                particleConstants, wall, restitution, adhesion, friction,
                momentCoeff, minReboundSpeed
            );
        })
    );
}


void Foam::wallInteractionEntry::reboundImpact
(
    wallImpact& out,
    const vector& U,
    const vector& Ut,
    const vector& nw,
    const vector& omega
) const
{
    // standardWallInteraction's rebound: U -= (1 + e) Un n towards the
    // wall, U -= mu Ut always
    out.outcome = brachDunn::Fate::rebound;
    out.U = U - mu_*Ut;
    if (out.un > 0)
    {
        out.U -= (1 + e_)*out.un*nw;
    }
    out.omega = omega;
    out.R = e_;
    out.unOut = max(-(out.U & nw), scalar(0));
    out.utOut = (1 - mu_)*out.ut;
}


Foam::wallImpact Foam::wallInteractionEntry::adhesiveImpact
(
    const brachDunn::Particle& particle,
    const vector& U,
    const vector& nw,
    const vector& omega
) const
{
    wallImpact out;
    const brachDunn::Impact3D impact = model_->impact
    (
        particle,
        {U.x(), U.y(), U.z()},
        {-nw.x(), -nw.y(), -nw.z()},
        {omega.x(), omega.y(), omega.z()}
    );
    const brachDunn::ImpactResult& r = impact.result;
    out.outcome = r.outcome;
    out.un = r.un;
    out.ut = r.ut;
    out.R = r.R;
    out.gamma = r.gamma;
    out.WA = r.WA;
    if (r.outcome == brachDunn::Fate::notApproaching)
    {
        out.U = U;
        out.omega = omega;
    }
    else if (r.outcome == brachDunn::Fate::rebound)
    {
        out.U = vector(impact.U.x, impact.U.y, impact.U.z);
        out.omega = vector(impact.omega.x, impact.omega.y, impact.omega.z);
        out.unOut = r.unOut;
        out.utOut = r.utOut;
    }
    return out;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::wallInteractionEntry::describe() const
{
    std::ostringstream os;
    os << name_.c_str() << ": " << typeName().c_str();
    if (!patchType_.empty())
    {
        os << " (also on " << patchType_.c_str() << " patches)";
    }
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
    if (resuspension_)
    {
        os  << "; resuspension " << resuspension_->model->describe()
            << " seed " << resuspension_->seed;
        const std::vector<std::string>& defaulted = resuspension_->defaulted;
        for (std::size_t i = 0; i < defaulted.size(); ++i)
        {
            os  << (i ? ", " : " (by default: ") << defaulted[i].c_str()
                << (i + 1 == defaulted.size() ? ")" : "");
        }
    }
    return os.str();
}


Foam::wallImpact Foam::wallInteractionEntry::impact
(
    const scalar d,
    const scalar rho,
    const vector& U,
    const vector& nw,
    const vector& omega
) const
{
    using brachDunn::Fate;

    wallImpact out;
    if (type_ == interaction::adhesive)
    {
        out = adhesiveImpact(brachDunn::Particle{d, rho}, U, nw, omega);
    }
    else
    {
        // The normal and tangential parts, where the core does not give them
        out.un = U & nw;
        const vector Ut = U - out.un*nw;
        out.ut = mag(Ut);
        switch (type_)
        {
            case interaction::escape: out.outcome = Fate::escape; break;
            case interaction::stick: out.outcome = Fate::capture; break;
            case interaction::rebound: reboundImpact(out, U, Ut, nw, omega); break;
            default:
                FatalErrorInFunction
                    << "Patch entry " << name_ << " has type none: it has no"
                    << " impact" << exit(FatalError);
        }
    }

    if (out.outcome == Fate::rebound || out.outcome == Fate::capture)
    {
        const scalar m = brachDunn::Particle{d, rho}.mass();
        out.energyLoss = 0.5*m*(magSqr(U) - magSqr(out.U));
    }
    return out;
}
