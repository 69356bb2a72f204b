// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "impactRecords.H"
#include "Pstream.H"
#include "releaseCompat.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

constexpr label recordSize = 15;

const char* const outcomeNames[] = {"rebound", "capture", "escape"};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::impactRecords::impactRecords
(
    const fileName& file,
    const label maxRecords,
    const wordList& patchNames
)
:
    maxRecords_(maxRecords),
    nWritten_(0),
    closed_(false),
    buffer_(),
    dropped_(false),
    patchNames_(patchNames),
    file_()
{
    if (maxRecords_ > 0 && Pstream::master())
    {
        file_ = std::make_unique<OFstream>(file);
        file_->precision(15);
        *file_
            << "time,patch,face,x,y,z,diameter,nParticle,un,ut,outcome,"
            << "R,WA,unOut,utOut" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

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
        for
        (
            const scalar v
          : {
                r.time, scalar(r.patch), scalar(r.face), r.position.x(),
                r.position.y(), r.position.z(), r.d, r.nParticle, r.un, r.ut,
                scalar(r.outcome), r.R, r.WA, r.unOut, r.utOut
            }
        )
        {
            mine[i++] = v;
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
                const scalar* r = &values[j*recordSize];
                os  << r[0] << ',' << patchNames_[label(r[1])] << ','
                    << label(r[2]) << ',' << r[3] << ',' << r[4] << ','
                    << r[5] << ',' << r[6] << ',' << r[7] << ','
                    << r[8] << ',' << r[9] << ','
                    << outcomeNames[label(r[10])] << ',' << r[11] << ','
                    << r[12] << ',' << r[13] << ',' << r[14] << nl;
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
