// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "gradeEfficiency.H"
#include "InputError.H"
#include "Pstream.H"
#include "scalarField.H"
#include "error.H"
#include "releaseCompat.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

string text(const scalar value)
{
    return brachDunn::toText(value);
}

constexpr const char* quantityNames[] =
{
    "injected", "captured", "escaped", "removed", "airborne"
};

//- The numbers of rows, in a flat list
scalarField flat(const List<gradeEfficiency::row>& rows)
{
    scalarField values(rows.size()*gradeEfficiency::nQuantities*3);
    label i = 0;
    for (const gradeEfficiency::row& r : rows)
    {
        for (const gradeEfficiency::sums& s : r)
        {
            values[i++] = s.parcels;
            values[i++] = s.particles;
            values[i++] = s.mass;
        }
    }
    return values;
}

void unflat(const scalarField& values, List<gradeEfficiency::row>& rows)
{
    label i = 0;
    for (gradeEfficiency::row& r : rows)
    {
        for (gradeEfficiency::sums& s : r)
        {
            s.parcels = values[i++];
            s.particles = values[i++];
            s.mass = values[i++];
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gradeEfficiency::gradeEfficiency
(
    const labelList& injectorIds,
    const scalarList& edges
)
:
    groups_(injectorIds, edges),
    totals_(groups_.size(), row()),
    step_(groups_.size(), row()),
    counted_(),
    countedAtImpact_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

const std::vector<Foam::gradeEfficiency::column>&
Foam::gradeEfficiency::columns()
{
    static const std::vector<column> table = []
    {
        std::vector<column> c;
        const std::pair<const char*, scalar sums::*> parts[] =
        {
            {"Parcels", &sums::parcels},
            {"Particles", &sums::particles},
            {"Mass", &sums::mass}
        };
        for (label q = 0; q < nQuantities; ++q)
        {
            for (const auto& [name, part] : parts)
            {
                c.push_back
                ({
                    quantityNames[q] + std::string(name),
                    [q, part = part](const row& r) { return r[q].*part; }
                });
            }
        }
        c.push_back({"capturedFraction", [](const row& r)
        {
            return
                r[injected].particles > 0
              ? r[captured].particles/r[injected].particles : 0;
        }});
        return c;
    }();
    return table;
}


void Foam::gradeEfficiency::fated
(
    const label group,
    const brachDunn::Fate outcome,
    const scalar nParticle,
    const scalar mass,
    const label origProc,
    const label origId
)
{
    if (outcome == brachDunn::Fate::resuspension)
    {
        // Airborne again: the captures are net of it
        sums& net = step_[group][captured];
        net.parcels -= 1;
        net.particles -= nParticle;
        net.mass -= mass;
        return;
    }
    if (outcome != brachDunn::Fate::capture && outcome != brachDunn::Fate::escape)
    {
        return;
    }
    // Caught in its injection step, before the cloud held it
    if (isNew(origProc, origId) && !countedAtImpact_.count({origProc, origId}))
    {
        step_[group][injected].add(nParticle, mass);
        countedAtImpact_.insert({origProc, origId});
    }
    step_[group][outcome == brachDunn::Fate::capture ? captured : escaped]
        .add(nParticle, mass);
}


void Foam::gradeEfficiency::leaving
(
    const label group,
    const scalar nParticle,
    const scalar mass,
    const label origProc,
    const label origId
)
{
    if (isNew(origProc, origId) && !countedAtImpact_.count({origProc, origId}))
    {
        step_[group][injected].add(nParticle, mass);
        countedAtImpact_.insert({origProc, origId});
    }
}


void Foam::gradeEfficiency::update(const List<parcel>& parcels)
{
    // This processor's new parcels, airborne ones, and highest origIds
    List<row> now(step_);
    label highest = counted_.size() - 1;
    for (const parcel& p : parcels)
    {
        highest = max(highest, p.origProc);
    }
    reduce(highest, maxOp<label>());
    labelList seen(highest + 1, -1);
    forAll(counted_, proc)
    {
        seen[proc] = counted_[proc];
    }
    for (const parcel& p : parcels)
    {
        if (isNew(p.origProc, p.origId) && !countedAtImpact_.count({p.origProc, p.origId}))
        {
            now[p.group][injected].add(p.nParticle, p.mass);
        }
        if (p.active)
        {
            now[p.group][airborne].add(p.nParticle, p.mass);
        }
        seen[p.origProc] = max(seen[p.origProc], p.origId);
    }
    for (const auto& [proc, id] : countedAtImpact_)
    {
        seen[proc] = max(seen[proc], id);
    }

    // Over processors
    scalarField values(flat(now));
    reduce(values, sumOp<scalarField>());
    unflat(values, now);
    compat::maxOverProcessors(seen);
    counted_ = seen;
    countedAtImpact_.clear();
    step_ = row();

    addStep(now);
}


void Foam::gradeEfficiency::addStep(const List<row>& now)
{
    // Removed: what left a class otherwise since the last step
    forAll(totals_, g)
    {
        row& t = totals_[g];
        const row& n = now[g];
        const auto removedPart = [&](scalar sums::*part)
        {
            return
                t[airborne].*part + n[injected].*part - n[captured].*part
              - n[escaped].*part - n[airborne].*part;
        };
        t[removed].parcels += removedPart(&sums::parcels);
        t[removed].particles += removedPart(&sums::particles);
        t[removed].mass += removedPart(&sums::mass);
        for (const quantity q : {injected, captured, escaped})
        {
            t[q].parcels += n[q].parcels;
            t[q].particles += n[q].particles;
            t[q].mass += n[q].mass;
        }
        t[airborne] = n[airborne];
    }
}


Foam::stringList Foam::gradeEfficiency::storedText() const
{
    stringList values;
    for (const scalar v : flat(totals_))
    {
        values.append(text(v));
    }
    for (const label id : counted_)
    {
        values.append(Foam::name(id));
    }
    return values;
}


void Foam::gradeEfficiency::restore(const stringList& values)
{
    if (values.empty())
    {
        return;
    }
    const label n = totals_.size()*nQuantities*3;
    if (values.size() < n)
    {
        FatalErrorInFunction
            << "The grade efficiency stored has " << values.size()
            << " values where at least " << n << " belong: it was made with"
            << " other sizeClasses or outputByInjectorId. Restart with the"
            << " same settings, or from a time without stored statistics"
            << exit(FatalError);
    }
    scalarField numbers(n);
    counted_.setSize(values.size() - n);
    forAll(values, i)
    {
        const std::string& value = values[i];
        char* end = nullptr;
        const scalar v = std::strtod(value.c_str(), &end);
        if (end == value.c_str() || *end != '\0')
        {
            FatalErrorInFunction
                << "The grade efficiency stored holds '" << value.c_str()
                << "', not a number" << exit(FatalError);
        }
        if (i < n) numbers[i] = v; else counted_[i - n] = label(v);
    }
    unflat(numbers, totals_);
}


void Foam::gradeEfficiency::writeHeader
(
    Ostream& os,
    const word& cloudName
) const
{
    os  << "# adhesiveWallInteraction grade efficiency of cloud " << cloudName
        << ": per size class (and injector), the parcels, particles and mass"
        << " [kg] injected since the start of the case, captured, escaped,"
        << " removed by OpenFOAM otherwise, and airborne now;"
        << " capturedFraction = capturedParticles/injectedParticles" << nl
        << "# time\tinjector\tdMin\tdMax";
    for (const column& c : columns())
    {
        os << '\t' << c.name.c_str();
    }
    os << endl;
}


void Foam::gradeEfficiency::write(Ostream& os, const word& timeName) const
{
    forAll(totals_, g)
    {
        os  << timeName << '\t' << groups_.injector(g).c_str()
            << '\t' << text(groups_.dMin(g)).c_str()
            << '\t' << text(groups_.dMax(g)).c_str();
        for (const column& c : columns())
        {
            os << '\t' << text(c.value(totals_[g])).c_str();
        }
        os << nl;
    }
    os.flush();
}
