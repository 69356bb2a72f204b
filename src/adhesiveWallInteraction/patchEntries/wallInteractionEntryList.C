// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "wallInteractionEntryList.H"
#include "checkedInput.H"
#include "releaseCompat.H"
#include "wallPolyPatch.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;


//- The entries of the patches list, which must be a list of dictionaries
PtrList<entry> patchEntries(const dictionary& coeffs)
{
    const char* form = "( <patch name, regex or group> { type ...; } ... )";
    const entry* e = checkedInput::find(coeffs, "patches");
    if (!e)
    {
        checkedInput::fail
        (
            coeffs, "patches", "missing", std::string("give a list ") + form
        );
    }
    // ( name { ... } name { ... } ), checked token by token before
    // OpenFOAM's list reader sees it
    using checkedInput::isPunctuation;
    bool good = !e->isDict();
    label i = good ? checkedInput::listStart(e->stream()) : -1;
    good = i >= 0;
    if (good)
    {
        const ITstream& tokens = e->stream();
        for (++i; good && i < tokens.size() && !isPunctuation(tokens[i], token::END_LIST);)
        {
            // A name, then a dictionary in braces
            good =
                (tokens[i].isWord() || tokens[i].isString())
             && i + 1 < tokens.size()
             && isPunctuation(tokens[i + 1], token::BEGIN_BLOCK);
            label depth = 0;
            for (i += 1; good && i < tokens.size(); ++i)
            {
                depth += isPunctuation(tokens[i], token::BEGIN_BLOCK);
                depth -= isPunctuation(tokens[i], token::END_BLOCK);
                if (!depth) { ++i; break; }
            }
            good = good && !depth;
        }
        good = good && i + 1 == tokens.size();
    }
    if (!good)
    {
        checkedInput::fail
        (
            coeffs, "patches", checkedInput::entryText(*e),
            std::string("must be a list ") + form
        );
    }
    return PtrList<entry>(e->stream());
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * //

bool Foam::wallInteractionEntryList::matches
(
    const keyType& key,
    const patch& p
)
{
    // The patch's name or one of its groups
    if (key.match(p.name))
    {
        return true;
    }
    for (const word& group : p.groups)
    {
        if (key.match(group))
        {
            return true;
        }
    }
    return false;
}


Foam::List<Foam::wallInteractionEntryList::patch>
Foam::wallInteractionEntryList::patchesOf(const polyBoundaryMesh& bMesh)
{
    List<patch> patches(bMesh.size());
    forAll(bMesh, patchi)
    {
        const polyPatch& pp = bMesh[patchi];
        patches[patchi] =
        {
            pp.name(), pp.type(), pp.inGroups(), bool(isA<wallPolyPatch>(pp)),
            compat::isConstraint(pp)
        };
    }
    return patches;
}


Foam::List<Foam::wallInteractionEntryList::patch>
Foam::wallInteractionEntryList::patchesOf(const PtrList<entry>& boundary)
{
    List<patch> patches(boundary.size());
    forAll(boundary, patchi)
    {
        const dictionary& dict = boundary[patchi].dict();
        patch& p = patches[patchi];
        p.name = boundary[patchi].keyword();
        p.type = checkedInput::readWord(dict, "type");
        p.wall = (p.type == wallPolyPatch::typeName);
        p.constraint = compat::isConstraintType(p.type);
        if (const entry* groups = checkedInput::find(dict, "inGroups"))
        {
            p.groups = wordList(groups->stream());
        }
        if
        (
            (p.wall || p.constraint)
         && std::find(p.groups.begin(), p.groups.end(), p.type)
         == p.groups.end()
        )
        {
            p.groups.append(p.type);
        }
    }
    return patches;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallInteractionEntryList::wallInteractionEntryList
(
    const dictionary& coeffs,
    const UList<patch>& patches,
    const wallInteractionEntry::particleMaterial& particle,
    const checkedInput::magnitudes& magnitudes
)
:
    entries_(),
    patchNames_(patches.size()),
    patchEntry_(patches.size(), -1),
    warnings_()
{
    forAll(patches, patchi)
    {
        patchNames_[patchi] = patches[patchi].name;
    }

    // Each entry read once, named after its place in the cloud properties
    // for messages
    for (const entry& e : patchEntries(coeffs))
    {
        dictionary entryDict(coeffs, e.dict());
        entryDict.name() = coeffs.name() + ".patches." + e.keyword();
        entries_.emplace_back(e.keyword(), entryDict, particle, magnitudes);
    }

    for (std::size_t entryi = 0; entryi < entries_.size(); ++entryi)
    {
        assign(entryi, patches, coeffs.name());
    }
    checkEveryPatch(coeffs, patches);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::wallInteractionEntryList::assign
(
    const std::size_t entryi,
    const UList<patch>& patches,
    const fileName& where
)
{
    // The first entry matching a patch applies to it
    const keyType& name = entries_[entryi].name();
    bool matched = false, used = false;
    forAll(patches, patchi)
    {
        if (matches(name, patches[patchi]))
        {
            matched = true;
            // Constraint patches only when the entry takes on their type
            const patch& p = patches[patchi];
            const bool eligible =
                !p.constraint || p.type == entries_[entryi].patchType();
            if (patchEntry_[patchi] < 0 && eligible)
            {
                patchEntry_[patchi] = entryi;
                used = true;
            }
        }
    }
    if (!matched)
    {
        warnings_.push_back
        (
            "No patch matches the entry " + name + " of " + where
        );
    }
    else if (!used)
    {
        warnings_.push_back
        (
            "The entry " + name + " of " + where + " is never"
            " used: the patches it matches are constraint patches (an"
            " entry takes on symmetry, symmetryPlane or wedge patches"
            " with patchType) or matched by an earlier entry (the first"
            " match applies)"
        );
    }
}


void Foam::wallInteractionEntryList::checkEveryPatch
(
    const dictionary& coeffs,
    const UList<patch>& patches
)
{
    std::string unmatched;
    forAll(patches, patchi)
    {
        const patch& p = patches[patchi];
        const wallInteractionEntry* e = entryOf(patchi);
        if (!e)
        {
            if (!p.constraint)
            {
                unmatched += (unmatched.empty() ? "" : " ") + p.name;
            }
        }
        else if
        (
            !p.constraint
         && e->type() == wallInteractionEntry::interaction::none
        )
        {
            warnings_.push_back
            (
                "Patch " + p.name + " has type none: "
              + (
                    p.wall
                  ? "a parcel reaching this wall stops the run (OpenFOAM"
                    " would leave it on the wall for ever)"
                  : "its parcels leave as OpenFOAM's system escapes,"
                    " outside this model's statistics and mass balance"
                )
              + "; use adhesive, rebound, stick or escape to have them"
                " handled and counted"
            );
        }
    }
    if (!unmatched.empty())
    {
        checkedInput::fail
        (
            coeffs, "patches", "(...)",
            "no entry matches the patches (" + unmatched + "); every patch"
            " that is not a constraint patch needs one"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::boolList Foam::wallInteractionEntryList::handled() const
{
    boolList handled(patchEntry_.size());
    forAll(handled, patchi)
    {
        const wallInteractionEntry* entry = entryOf(patchi);
        handled[patchi] =
            entry && entry->type() != wallInteractionEntry::interaction::none;
    }
    return handled;
}
