// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "fateStatistics.H"
#include "InputError.H"
#include "Pstream.H"
#include "scalarField.H"
#include "error.H"

#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A number as the shortest text that reads back as the same number
string text(const scalar value)
{
    return brachDunn::toText(value);
}


//- Mean of a particle-weighted sum
scalar mean(const scalar sum, const scalar particles)
{
    return particles > 0 ? sum/particles : 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fateStatistics::fateStatistics
(
    const wordList& meshPatchNames,
    const boolList& withStatistics,
    const labelList& injectorIds,
    const scalarList& sizeClassEdges
)
:
    patchNames_(),
    patchIndex_(meshPatchNames.size(), -1),
    groups_(injectorIds, sizeClassEdges),
    run_(),
    stored_()
{
    forAll(meshPatchNames, patchi)
    {
        if (withStatistics[patchi])
        {
            patchIndex_[patchi] = patchNames_.size();
            patchNames_.append(meshPatchNames[patchi]);
        }
    }
    run_.setSize(patchNames_.size()*nGroups(), row());
    stored_ = run_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::fateStatistics::rowOf
(
    const label meshPatch,
    const label injectorId,
    const scalar d
) const
{
    return patchIndex_[meshPatch]*nGroups() + groups_.of(injectorId, d);
}


void Foam::fateStatistics::add
(
    const label row,
    const Fate outcome,
    const scalar nParticle,
    const scalar mass,
    const scalar speed,
    const scalar angle
)
{
    sums& s = run_[row][brachDunn::countedIndex(outcome)];
    s.parcels += 1;
    s.particles += nParticle;
    s.mass += mass;
    if (outcome != Fate::escape)
    {
        s.speed += nParticle*speed;
        s.angle += nParticle*angle;
    }
}


Foam::List<Foam::fateStatistics::row> Foam::fateStatistics::totals() const
{
    scalarField values(run_.size()*rowSize);
    label i = 0;
    for (const row& r : run_)
    {
        for (const sums& s : r)
        {
            for (const scalar v : {s.parcels, s.particles, s.mass, s.speed, s.angle})
            {
                values[i++] = v;
            }
        }
    }
    reduce(values, sumOp<scalarField>());

    List<row> total(stored_);
    i = 0;
    for (row& r : total)
    {
        for (sums& s : r)
        {
            for (scalar* v : {&s.parcels, &s.particles, &s.mass, &s.speed, &s.angle})
            {
                *v += values[i++];
            }
        }
    }
    return total;
}


void Foam::fateStatistics::store(const List<row>& totals)
{
    stored_ = totals;
    run_ = row();
}


Foam::stringList Foam::fateStatistics::storedText
(
    const List<row>& totals,
    const label patch
) const
{
    stringList values;
    for (label j = 0; j < nGroups(); ++j)
    {
        for (const sums& s : totals[patch*nGroups() + j])
        {
            for (const scalar v : {s.parcels, s.particles, s.mass, s.speed, s.angle})
            {
                values.append(text(v));
            }
        }
    }
    return values;
}


void Foam::fateStatistics::restore(const label patch, const stringList& values)
{
    if (values.empty())
    {
        return;
    }
    // Totals stored before resuspension was counted have no such sums
    constexpr label oldRowSize = rowSize - 5;
    const bool old = values.size() == nGroups()*oldRowSize;
    if (values.size() != nGroups()*rowSize && !old)
    {
        FatalErrorInFunction
            << "The statistics stored for patch " << patchNames_[patch]
            << " have " << values.size() << " values where "
            << nGroups()*rowSize << " belong: they were made with other"
            << " sizeClasses or outputByInjectorId. Restart with the same"
            << " settings, or from a time without stored statistics"
            << exit(FatalError);
    }
    label i = 0;
    for (label j = 0; j < nGroups(); ++j)
    {
        for (sums& s : stored_[patch*nGroups() + j])
        {
            if (old && &s == &stored_[patch*nGroups() + j].back())
            {
                continue;
            }
            for (scalar* v : {&s.parcels, &s.particles, &s.mass, &s.speed, &s.angle})
            {
                const std::string& value = values[i++];
                char* end = nullptr;
                *v = std::strtod(value.c_str(), &end);
                if (end == value.c_str() || *end != '\0')
                {
                    FatalErrorInFunction
                        << "The statistics stored for patch "
                        << patchNames_[patch] << " hold '" << value.c_str()
                        << "', not a number" << exit(FatalError);
                }
            }
        }
    }
}


Foam::scalar Foam::fateStatistics::total
(
    const List<row>& totals,
    const Fate outcome,
    scalar sums::*quantity
)
{
    scalar sum = 0;
    for (const row& r : totals)
    {
        sum += of(r, outcome).*quantity;
    }
    return sum;
}


const std::vector<Foam::fateStatistics::column>&
Foam::fateStatistics::columns()
{
    // One line per column
    static const std::vector<column> table = []
    {
        std::vector<column> c;
        const std::pair<const char*, scalar sums::*> quantities[] =
        {
            {"Parcels", &sums::parcels},
            {"Particles", &sums::particles},
            {"Mass", &sums::mass}
        };
        for (const auto& [name, q] : quantities)
        {
            c.push_back({std::string("impact") + name, [q = q](const row& r)
            {
                scalar sum = 0;
                for (const Fate fate : brachDunn::impactFates)
                {
                    sum += of(r, fate).*q;
                }
                return sum;
            }});
        }
        for (const Fate fate : brachDunn::countedFates)
        {
            for (const auto& [name, q] : quantities)
            {
                c.push_back
                ({
                    brachDunn::fateName(fate) + std::string(name),
                    [fate, q = q](const row& r) { return of(r, fate).*q; }
                });
            }
        }
        for (const Fate fate : {Fate::rebound, Fate::capture})
        {
            c.push_back({brachDunn::fateName(fate) + std::string("Speed"),
                [fate](const row& r)
                {
                    return mean(of(r, fate).speed, of(r, fate).particles);
                }});
            c.push_back({brachDunn::fateName(fate) + std::string("Angle"),
                [fate](const row& r)
                {
                    return mean(of(r, fate).angle, of(r, fate).particles);
                }});
        }
        return c;
    }();
    return table;
}


void Foam::fateStatistics::writeHeader
(
    Ostream& os,
    const word& cloudName
) const
{
    os  << "# adhesiveWallInteraction statistics of cloud " << cloudName
        << ": totals since the start of the case, one row per time, patch,"
        << " injector and size class; masses [kg], mean impact speed [m/s]"
        << " and angle from the wall normal [deg] of the particles" << nl
        << "# time\tpatch\tinjector\tdMin\tdMax";
    for (const column& c : columns())
    {
        os << '\t' << c.name.c_str();
    }
    os  << endl;
}


void Foam::fateStatistics::write
(
    Ostream& os,
    const word& timeName,
    const List<row>& totals
) const
{
    forAll(patchNames_, patch)
    {
        for (label group = 0; group < nGroups(); ++group)
        {
            const row& r = totals[patch*nGroups() + group];
            os  << timeName << '\t' << patchNames_[patch] << '\t'
                << groups_.injector(group).c_str()
                << '\t' << text(groups_.dMin(group)).c_str()
                << '\t' << text(groups_.dMax(group)).c_str();
            for (const column& c : columns())
            {
                os << '\t' << text(c.value(r)).c_str();
            }
            os << nl;
        }
    }
    os.flush();
}


void Foam::fateStatistics::print(Ostream& os, const List<row>& totals) const
{
    forAll(patchNames_, patch)
    {
        for (label group = 0; group < nGroups(); ++group)
        {
            const row& r = totals[patch*nGroups() + group];
            os  << "    adhesiveWallInteraction patch "
                << patchNames_[patch];
            if (groups_.byInjector())
            {
                os << " injector " << groups_.injector(group).c_str();
            }
            if (groups_.bySize())
            {
                os  << " d [" << text(groups_.dMin(group)).c_str() << ", "
                    << text(groups_.dMax(group)).c_str() << ") m";
            }
            const sums& b = of(r, Fate::rebound);
            const sums& c = of(r, Fate::capture);
            const sums& e = of(r, Fate::escape);
            os  << " (parcels, particles, mass)" << nl
                << "      - impacts                     = "
                << b.parcels + c.parcels + e.parcels << ", "
                << b.particles + c.particles + e.particles << ", "
                << b.mass + c.mass + e.mass << nl
                << "      - rebounds                    = "
                << b.parcels << ", " << b.particles << ", " << b.mass << nl
                << "      - captures                    = "
                << c.parcels << ", " << c.particles << ", " << c.mass << nl
                << "      - escapes                     = "
                << e.parcels << ", " << e.particles << ", " << e.mass << nl
                << "      - resuspended                 = "
                << of(r, Fate::resuspension).parcels << ", "
                << of(r, Fate::resuspension).particles << ", "
                << of(r, Fate::resuspension).mass << nl
                << "      - captured: mean impact speed, angle = "
                << mean(c.speed, c.particles) << " m/s, "
                << mean(c.angle, c.particles) << " deg" << nl
                << "      - rebounded: mean impact speed, angle = "
                << mean(b.speed, b.particles) << " m/s, "
                << mean(b.angle, b.particles) << " deg" << nl;
        }
    }
}


void Foam::fateStatistics::printSummary
(
    Ostream& os,
    const List<row>& totals
) const
{
    forAll(patchNames_, patch)
    {
        sums impacts, captures, escapes;
        for (label group = 0; group < nGroups(); ++group)
        {
            const row& r = totals[patch*nGroups() + group];
            for (const Fate fate : brachDunn::impactFates)
            {
                impacts.parcels += of(r, fate).parcels;
                impacts.particles += of(r, fate).particles;
            }
            captures.parcels += of(r, Fate::capture).parcels;
            captures.particles += of(r, Fate::capture).particles;
            escapes.parcels += of(r, Fate::escape).parcels;
            escapes.particles += of(r, Fate::escape).particles;
        }
        os  << "    adhesiveWallInteraction " << patchNames_[patch]
            << " (parcels, particles): impacts " << impacts.parcels << ", "
            << impacts.particles << "; captured " << captures.parcels << ", "
            << captures.particles << "; escaped " << escapes.parcels << ", "
            << escapes.particles << nl;
    }
}
