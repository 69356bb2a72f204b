// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "impactRecords.H"
#include "Pstream.H"
#include "releaseCompat.H"
#include "Fate.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- How a column is written
enum class format { number, label, patch, fate };

//- The columns of impacts.csv: one line each
const struct
{
    const char* name;
    scalar impactRecords::record::*value;
    format form;
} columns[] =
{
    {"time", &impactRecords::record::time, format::number},
    {"patch", &impactRecords::record::patch, format::patch},
    {"face", &impactRecords::record::face, format::label},
    {"x", &impactRecords::record::x, format::number},
    {"y", &impactRecords::record::y, format::number},
    {"z", &impactRecords::record::z, format::number},
    {"diameter", &impactRecords::record::d, format::number},
    {"nParticle", &impactRecords::record::nParticle, format::number},
    {"un", &impactRecords::record::un, format::number},
    {"ut", &impactRecords::record::ut, format::number},
    {"outcome", &impactRecords::record::outcome, format::fate},
    {"R", &impactRecords::record::R, format::number},
    {"WA", &impactRecords::record::WA, format::number},
    {"unOut", &impactRecords::record::unOut, format::number},
    {"utOut", &impactRecords::record::utOut, format::number},
};

constexpr label recordSize = sizeof(columns)/sizeof(columns[0]);

static_assert
(
    sizeof(impactRecords::record) == recordSize*sizeof(scalar),
    "every member of impactRecords::record is a column of impacts.csv"
);

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::impactRecords::impactRecords
(
    const fileName& file,
    const label maxRecords,
    const wordList& patchNames,
    const boolList& recorded
)
:
    maxRecords_(maxRecords),
    nWritten_(0),
    closed_(false),
    buffer_(),
    dropped_(false),
    patchNames_(patchNames),
    recorded_(recorded),
    file_()
{
    if (maxRecords_ > 0 && Pstream::master())
    {
        file_ = std::make_unique<OFstream>(file);
        file_->precision(15);
        for (label c = 0; c < recordSize; ++c)
        {
            *file_ << (c ? "," : "") << columns[c].name;
        }
        *file_ << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::impactRecords::writeLine(Ostream& os, const scalar* r) const
{
    for (label c = 0; c < recordSize; ++c)
    {
        os << (c ? "," : "");
        switch (columns[c].form)
        {
            case format::number: os << r[c]; break;
            case format::label: os << label(r[c]); break;
            case format::patch: os << patchNames_[label(r[c])]; break;
            case format::fate:
                os << brachDunn::fateName(brachDunn::Fate(label(r[c])));
                break;
        }
    }
    os << nl;
}


void Foam::impactRecords::write()
{
    if (!active())
    {
        return;
    }

    // Each processor's records as numbers, gathered on the master
    List<scalarList> buffers(Pstream::nProcs());
    scalarList& mine = buffers[Pstream::myProcNo()];
    mine.setSize(buffer_.size()*recordSize + 1);
    label i = 0;
    for (const record& r : buffer_)
    {
        for (const auto& column : columns)
        {
            mine[i++] = r.*column.value;
        }
    }
    mine[i] = dropped_;
    buffer_.clear();
    dropped_ = false;
    Pstream::gatherList(buffers);

    if (Pstream::master())
    {
        OFstream& os = *file_;
        bool capped = false;
        for (const scalarList& values : buffers)
        {
            const label n = (values.size() - 1)/recordSize;
            capped = capped || values.last() > 0;
            for (label j = 0; j < n; ++j)
            {
                if (nWritten_ >= maxRecords_)
                {
                    capped = true;
                    break;
                }
                writeLine(os, &values[j*recordSize]);
                ++nWritten_;
            }
        }
        if (capped)
        {
            os  << "# capped at maxImpactRecords = " << maxRecords_
                << ": later impacts are not recorded" << nl;
            closed_ = true;
        }
        os.flush();
    }
    compat::broadcast(nWritten_);
    compat::broadcast(closed_);
}
