#include "AdhesiveWallInteraction.H"
#include "checkedInput.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "wallPolyPatch.H"
#include "mathematicalConstants.H"

#include <type_traits>
#include <utility>

// * * * * * * * * * * * * * * * Local Helpers * * * * * * * * * * * * * * //

namespace Foam
{
namespace adhesiveWallInteractionDetail
{

//- Parcels of colliding clouds carry angular momentum (and their cloud's
//  constant properties carry youngsModulus and poissonsRatio)
template<class Parcel, class = void>
struct isColliding : std::false_type {};

template<class Parcel>
struct isColliding
<
    Parcel,
    std::void_t<decltype(std::declval<Parcel&>().angularMomentum())>
>
: std::true_type {};

//- Parcels of MPPIC clouds carry a velocity correction
template<class Parcel, class = void>
struct isMPPIC : std::false_type {};

template<class Parcel>
struct isMPPIC
<
    Parcel,
    std::void_t<decltype(std::declval<Parcel&>().UCorrect())>
>
: std::true_type {};

inline brachDunn::Vector3 toCore(const vector& v)
{
    return {v.x(), v.y(), v.z()};
}

inline vector fromCore(const brachDunn::Vector3& v)
{
    return vector(v.x, v.y, v.z);
}

//- Columns of one impact record
enum recordColumn : label
{
    rTime, rPatch, rFace, rX, rY, rZ, rDiameter, rNParticle,
    rUn, rUt, rFate, rR, rWA, rUnOut, rUtOut, recordSize
};

const char* const fateNames[] = {"rebound", "capture", "escape"};

} // End namespace adhesiveWallInteractionDetail
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::fileName Foam::AdhesiveWallInteraction<CloudType>::outputDir() const
{
    // As OpenFOAM's cloud function objects: postProcessing/lagrangian/<cloud>
    const Time& time = this->owner().mesh().time();
    return
        time.rootPath()/time.globalCaseName()/"postProcessing"/"lagrangian"
       /this->owner().name()/typeName/compat::timeName(time);
}


template<class CloudType>
brachDunn::ElasticMaterial
Foam::AdhesiveWallInteraction<CloudType>::particleMaterial() const
{
    using parcelType = typename CloudType::parcelType;
    const dictionary& coeffs = this->coeffs();

    if (const dictionary* particleDict = findParticleDict(coeffs))
    {
        return readElasticMaterial(*particleDict);
    }

    if constexpr (adhesiveWallInteractionDetail::isColliding<parcelType>::value)
    {
        const auto& props = this->owner().constProps();
        const brachDunn::ElasticMaterial material
        {
            props.youngsModulus(), props.poissonsRatio()
        };
        checkedInput::coreCall(coeffs, [&]{ material.check(); });
        return material;
    }

    FatalIOErrorInFunction(coeffs)
        << "In dictionary " << coeffs.name() << ": keyword 'particle' is"
        << " missing. Clouds that are not colliding clouds need the"
        << " particle's elastic constants: particle { E <Pa>; nu <->; }"
        << nl << exit(FatalIOError);
    return {};
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::count
(
    const typename CloudType::parcelType& p,
    const polyPatch& pp,
    fate outcome,
    scalar un,
    scalar ut,
    scalar R,
    scalar WA,
    scalar unOut,
    scalar utOut
)
{
    using namespace adhesiveWallInteractionDetail;

    const scalar nParticle = p.nParticle();
    const scalar mass = nParticle*p.mass();
    const scalar speed = Foam::sqrt(un*un + ut*ut);
    const scalar angle = Foam::atan2(ut, un)*180/constant::mathematical::pi;

    // Columns are fate-major: (parcels, particles, mass) of rebound, capture,
    // escape, then (speed, angle) sums of rebound and capture
    static_assert
    (
        captureParcels == 3 && escapeParcels == 6
     && captureSpeedSum == reboundSpeedSum + 2,
        "statistic columns out of the fate order"
    );
    scalar* s = &stats_[row(p, pp)*nStatistics];
    const label column = 3*label(outcome);
    s[column] += 1;
    s[column + 1] += nParticle;
    s[column + 2] += mass;
    if (outcome != fate::escape)
    {
        const label sums = reboundSpeedSum + 2*label(outcome);
        s[sums] += nParticle*speed;
        s[sums + 1] += nParticle*angle;
    }

    if (writeFields_ && outcome != fate::rebound)
    {
        const label facei = pp.whichFace(p.face());
        if (outcome == fate::capture)
        {
            massStickPtr_->boundaryFieldRef()[pp.index()][facei] += mass;
            nStickPtr_->boundaryFieldRef()[pp.index()][facei] += nParticle;
        }
        else
        {
            massEscapePtr_->boundaryFieldRef()[pp.index()][facei] += mass;
        }
    }

    if (maxImpactRecords_ > 0 && !recordsClosed_)
    {
        const Time& time = this->owner().mesh().time();
        const vector position =
            compat::position(p, this->owner().mesh());
        const scalar record[recordSize] =
        {
            time.value() - (1 - p.stepFraction())*time.deltaTValue(),
            scalar(pp.index()),
            scalar(pp.whichFace(p.face())),
            position.x(), position.y(), position.z(),
            p.d(), nParticle, un, ut, scalar(label(outcome)),
            R, WA, unOut, utOut
        };
        for (const scalar value : record)
        {
            recordBuffer_.append(value);
        }
    }
}


template<class CloudType>
Foam::string Foam::AdhesiveWallInteraction<CloudType>::rowName
(
    const label row
) const
{
    const polyBoundaryMesh& bMesh = compat::boundaryMesh(this->owner().mesh());
    string name(bMesh[statPatches_[row/nInjectors_]].name());
    if (injectorIds_.size())
    {
        name += " injector " + Foam::name(injectorIds_[row % nInjectors_]);
    }
    return name;
}


template<class CloudType>
Foam::scalarField
Foam::AdhesiveWallInteraction<CloudType>::totalStatistics()
{
    scalarField total(stats_);
    reduce(total, sumOp<scalarField>());

    // Earlier runs: one list of nInjectors rows per patch
    const polyBoundaryMesh& bMesh = compat::boundaryMesh(this->owner().mesh());
    const label patchSize = nInjectors_*nStatistics;
    forAll(statPatches_, patchRow)
    {
        scalarList stored(patchSize, Zero);
        this->getModelProperty(bMesh[statPatches_[patchRow]].name(), stored);
        if (stored.size() == patchSize)
        {
            for (label i = 0; i < patchSize; ++i)
            {
                total[patchRow*patchSize + i] += stored[i];
            }
        }
    }
    return total;
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::writeImpactRecords()
{
    using namespace adhesiveWallInteractionDetail;

    if (maxImpactRecords_ <= 0)
    {
        return;
    }

    List<scalarList> buffers(Pstream::nProcs());
    buffers[Pstream::myProcNo()].transfer(recordBuffer_);
    Pstream::gatherList(buffers);
    recordBuffer_.clear();

    if (Pstream::master() && !recordsClosed_)
    {
        OFstream& os = *recordFilePtr_;
        const polyBoundaryMesh& bMesh =
            compat::boundaryMesh(this->owner().mesh());
        for (const scalarList& buffer : buffers)
        {
            for (label start = 0; start < buffer.size(); start += recordSize)
            {
                if (nImpactRecords_ >= maxImpactRecords_)
                {
                    os  << "# capped at maxImpactRecords = "
                        << maxImpactRecords_
                        << ": later impacts are not recorded" << endl;
                    recordsClosed_ = true;
                    break;
                }
                const scalar* r = &buffer[start];
                os  << r[rTime] << ','
                    << bMesh[label(r[rPatch])].name() << ','
                    << label(r[rFace]) << ','
                    << r[rX] << ',' << r[rY] << ',' << r[rZ] << ','
                    << r[rDiameter] << ',' << r[rNParticle] << ','
                    << r[rUn] << ',' << r[rUt] << ','
                    << fateNames[label(r[rFate])] << ','
                    << r[rR] << ',' << r[rWA] << ','
                    << r[rUnOut] << ',' << r[rUtOut] << nl;
                ++nImpactRecords_;
            }
            if (recordsClosed_) break;
        }
        os.flush();
    }
    compat::broadcast(recordsClosed_);
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::massBalance
(
    Ostream& os,
    const scalarField& total
) const
{
    scalar injected = 0;
    for (const auto& injector : this->owner().injectors())
    {
        injected += injector.massInjected();
    }

    scalar airborne = 0;
    for (const auto& p : this->owner())
    {
        if (compat::isActive(p))
        {
            airborne += p.nParticle()*p.mass();
        }
    }
    reduce(airborne, sumOp<scalar>());

    scalar captured = 0, escaped = 0;
    for (label start = 0; start < total.size(); start += nStatistics)
    {
        captured += total[start + captureMass];
        escaped += total[start + escapeMass];
    }

    os  << "    adhesiveWallInteraction mass balance [kg]" << nl
        << "      - injected                    = " << injected << nl
        << "      - airborne                    = " << airborne << nl
        << "      - captured                    = " << captured << nl
        << "      - escaped                     = " << escaped << nl
        << "      - injected - (airborne + captured + escaped) = "
        << injected - (airborne + captured + escaped) << nl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::AdhesiveWallInteraction<CloudType>::AdhesiveWallInteraction
(
    const dictionary& dict,
    CloudType& cloud
)
:
    compat::PatchInteractionModel<CloudType>(dict, cloud, typeName),
    entries_(),
    patchEntry_(compat::boundaryMesh(cloud.mesh()).size(), -1),
    statPatches_(),
    statRow_(compat::boundaryMesh(cloud.mesh()).size(), -1),
    removeCaptured_(false),
    writeFields_
    (
        checkedInput::readSwitch(this->coeffs(), "writeFields", false)
    ),
    injectorIndex_(),
    injectorIds_(),
    nInjectors_(1),
    stats_(),
    massStickPtr_(),
    nStickPtr_(),
    massEscapePtr_(),
    maxImpactRecords_
    (
        checkedInput::readCount(this->coeffs(), "maxImpactRecords", 0)
    ),
    nImpactRecords_(0),
    recordsClosed_(false),
    writeToFile_(checkedInput::readSwitch(this->coeffs(), "writeToFile", false)),
    recordBuffer_(),
    recordFilePtr_(),
    statsFilePtr_()
{
    const dictionary& coeffs = this->coeffs();
    const polyBoundaryMesh& bMesh = compat::boundaryMesh(cloud.mesh());

    // This model's keywords, and those its OpenFOAM base classes read
    wordList keywords
    {
        "particle", "capture", "writeFields", "outputByInjectorId",
        "writeToFile", "maxImpactRecords", "patches"
    };
    keywords.append(compat::baseKeywords());
    checkedInput::requireKnownKeywords
    (
        coeffs, keywords, std::string(typeName) + " coefficients"
    );

    removeCaptured_ =
        checkedInput::readWord
        (
            coeffs, "capture", "stick", {"stick", "remove"}
        ) == "remove";
    if constexpr
    (
        adhesiveWallInteractionDetail::isMPPIC
        <
            typename CloudType::parcelType
        >::value
    )
    {
        if (!removeCaptured_)
        {
            WarningInFunction
                << "capture stick in an MPPIC cloud: OpenFOAM v1912's MPPIC"
                << " tracking can hang on parcels left inactive on a wall"
                << " (its own localInteraction stick does too); prefer"
                << " capture remove" << endl;
        }
    }

    // The patch entries, read and checked once
    if (!checkedInput::find(coeffs, "patches"))
    {
        FatalIOErrorInFunction(coeffs)
            << "In dictionary " << coeffs.name() << ": keyword 'patches' is"
            << " missing: give a list of (patch name or regex) { type ...; }"
            << nl << exit(FatalIOError);
    }
    PtrList<entry> patchList(checkedInput::find(coeffs, "patches")->stream());
    bool anyAdhesive = false;
    for (const entry& e : patchList)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(coeffs)
                << "In dictionary " << coeffs.name() << ": entry "
                << e.keyword() << " of 'patches' must be a"
                << " dictionary: name { type ...; }" << nl
                << exit(FatalIOError);
        }
        anyAdhesive =
            anyAdhesive
         || (
                checkedInput::find(e.dict(), "type")
             && checkedInput::readWord(e.dict(), "type") == "adhesive"
            );
    }

    // The particle's elastic constants matter to adhesive entries only
    brachDunn::ElasticMaterial particle{0, 0};
    if (anyAdhesive)
    {
        particle = particleMaterial();
        Info<< "    particle: E " << particle.E << " nu " << particle.nu
            << (
                   findParticleDict(coeffs)
                 ? " (particle)"
                 : " (constantProperties youngsModulus, poissonsRatio)"
               )
            << nl;
    }

    entries_.setSize(patchList.size());
    forAll(patchList, i)
    {
        // Named after its place in the cloud properties, for error messages
        dictionary entryDict(coeffs, patchList[i].dict());
        entryDict.name() =
            coeffs.name() + ".patches." + patchList[i].keyword();
        entries_.set
        (
            i,
            new wallInteractionEntry(patchList[i].keyword(), entryDict, particle)
        );
    }

    // Patch matching happens here, once: the first entry matching a patch
    // applies to it
    forAll(entries_, i)
    {
        DynamicList<label> ids;
        forAll(bMesh, patchi)
        {
            if (entries_[i].name().match(bMesh[patchi].name()))
            {
                ids.append(patchi);
            }
        }
        if (ids.empty())
        {
            WarningInFunction
                << "No patch matches the entry " << entries_[i].name()
                << " of " << coeffs.name() << endl;
        }
        bool used = false;
        for (const label patchi : ids)
        {
            if (patchEntry_[patchi] < 0 && !compat::isConstraint(bMesh[patchi]))
            {
                patchEntry_[patchi] = i;
                used = true;
            }
        }
        if (ids.size() && !used)
        {
            WarningInFunction
                << "The entry " << entries_[i].name() << " of "
                << coeffs.name() << " is never used: the patches it matches"
                << " are constraint patches or matched by an earlier entry"
                << " (the first match applies)" << endl;
        }
    }

    wordList unmatched;
    DynamicList<label> statPatches;
    forAll(bMesh, patchi)
    {
        if (compat::isConstraint(bMesh[patchi]))
        {
            continue;
        }
        if (patchEntry_[patchi] < 0)
        {
            unmatched.append(bMesh[patchi].name());
        }
        else if
        (
            entries_[patchEntry_[patchi]].type()
         == wallInteractionEntry::interaction::none
        )
        {
            WarningInFunction
                << "Patch " << bMesh[patchi].name() << " has type none: "
                << (
                       isA<wallPolyPatch>(bMesh[patchi])
                     ? "a parcel reaching this wall stops the run (OpenFOAM"
                       " would leave it on the wall for ever)"
                     : "its parcels leave as OpenFOAM's system escapes,"
                       " outside this model's statistics and mass balance"
                   )
                << "; use adhesive, rebound, stick or escape to have them"
                << " handled and counted" << endl;
        }
        else
        {
            statRow_[patchi] = statPatches.size();
            statPatches.append(patchi);
        }
    }
    if (unmatched.size())
    {
        FatalIOErrorInFunction(coeffs)
            << "In dictionary " << coeffs.name() << ": no entry of 'patches'"
            << " matches the patches " << unmatched
            << "; every patch that is not a constraint patch needs one"
            << nl << exit(FatalIOError);
    }
    statPatches_.transfer(statPatches);
    // By injector, as standardWallInteraction's outputByInjectorId
    if (checkedInput::readSwitch(coeffs, "outputByInjectorId", false))
    {
        if (!compat::parcelsKnowTheirInjector)
        {
            checkedInput::fail
            (
                coeffs, "outputByInjectorId", "yes",
                std::string("not available on ") + compat::flavour()
              + "'s OpenFOAM, whose parcels do not carry their injector"
            );
        }
        for (const auto& injector : cloud.injectors())
        {
            const label id = compat::injectorId(injector);
            injectorIndex_[id] = injectorIds_.size();
            injectorIds_.append(id);
        }
        nInjectors_ = max(injectorIds_.size(), label(1));
    }
    stats_.setSize(statPatches_.size()*nInjectors_*nStatistics, Zero);

    for (const wallInteractionEntry& e : entries_)
    {
        Info<< "    " << e.describe().c_str() << nl;
    }

    if (writeFields_)
    {
        const fvMesh& mesh = cloud.mesh();
        const auto field = [&](const word& name, const dimensionSet& dims)
        {
            return std::make_unique<volScalarField>
            (
                IOobject
                (
                    cloud.name() + ":" + name,
                    compat::timeName(mesh.time()),
                    mesh,
                    IOobject::READ_IF_PRESENT,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar("zero", dims, 0)
            );
        };
        massStickPtr_ = field("massStick", dimMass);
        nStickPtr_ = field("nStick", dimless);
        massEscapePtr_ = field("massEscape", dimMass);
        Info<< "    Deposited mass and number per face written to "
            << cloud.name() << ":massStick and " << cloud.name()
            << ":nStick, escaped mass to " << cloud.name() << ":massEscape"
            << endl;
    }

    if (Pstream::master() && (writeToFile_ || maxImpactRecords_ > 0))
    {
        mkDir(outputDir());
    }
    if (Pstream::master() && writeToFile_)
    {
        statsFilePtr_.reset(new OFstream(outputDir()/"statistics.dat"));
        OFstream& os = *statsFilePtr_;
        os  << "# adhesiveWallInteraction statistics of cloud "
            << cloud.name() << ", totals since the start of the case" << nl
            << "# Time";
        const wordList names
        {
            "reboundParcels", "reboundParticles", "reboundMass",
            "captureParcels", "captureParticles", "captureMass",
            "escapeParcels", "escapeParticles", "escapeMass",
            "reboundMeanSpeed", "reboundMeanAngle",
            "captureMeanSpeed", "captureMeanAngle"
        };
        for (label row = 0; row < statPatches_.size()*nInjectors_; ++row)
        {
            for (const word& name : names)
            {
                os << tab << rowName(row).c_str() << ':' << name;
            }
        }
        os << endl;
    }
    if (Pstream::master() && maxImpactRecords_ > 0)
    {
        recordFilePtr_.reset(new OFstream(outputDir()/"impacts.csv"));
        recordFilePtr_->precision(15);
        *recordFilePtr_
            << "time,patch,face,x,y,z,diameter,nParticle,un,ut,outcome,"
            << "R,WA,unOut,utOut" << endl;
    }
}


template<class CloudType>
Foam::AdhesiveWallInteraction<CloudType>::AdhesiveWallInteraction
(
    const AdhesiveWallInteraction<CloudType>& pim
)
:
    compat::PatchInteractionModel<CloudType>(pim),
    entries_(pim.entries_),
    patchEntry_(pim.patchEntry_),
    statPatches_(pim.statPatches_),
    statRow_(pim.statRow_),
    removeCaptured_(pim.removeCaptured_),
    writeFields_(false),
    injectorIndex_(pim.injectorIndex_),
    injectorIds_(pim.injectorIds_),
    nInjectors_(pim.nInjectors_),
    stats_(pim.stats_),
    massStickPtr_(),
    nStickPtr_(),
    massEscapePtr_(),
    maxImpactRecords_(0),
    nImpactRecords_(0),
    recordsClosed_(true),
    writeToFile_(false),
    recordBuffer_(),
    recordFilePtr_(),
    statsFilePtr_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::correct
(
    typename CloudType::parcelType& p,
    const polyPatch& pp,
    bool& keepParticle
)
{
    using namespace adhesiveWallInteractionDetail;
    using interaction = wallInteractionEntry::interaction;

    const label entryi = patchEntry_[pp.index()];
    if (entryi < 0)
    {
        return false;
    }
    const wallInteractionEntry& entry = entries_[entryi];
    if (entry.type() == interaction::none)
    {
        if (isA<wallPolyPatch>(pp))
        {
            // Declined, OpenFOAM v1912 leaves the parcel on the wall face
            // and the time step never ends: stop with the reason instead
            FatalErrorInFunction
                << "Parcel at " << compat::position(p, this->owner().mesh())
                << " hit the wall patch "
                << pp.name() << ", whose entry " << entry.name()
                << " has type none: nothing would move it off the wall."
                << " Give walls an adhesive, rebound, stick or escape entry"
                << exit(FatalError);
        }
        return false;
    }

    vector nw, Up;
    this->owner().patchData(p, pp, nw, Up);

    // Velocity relative to the wall; nw points out of the domain
    vector& U = p.U();
    const vector Urel = U - Up;
    const scalar Un = Urel & nw;
    const vector Ut = Urel - Un*nw;
    const scalar ut = mag(Ut);

    const auto capture = [&]()
    {
        keepParticle = !removeCaptured_;
        compat::setActive(p, false);
        U = Zero;
        if constexpr (isColliding<typename CloudType::parcelType>::value)
        {
            p.angularMomentum() = Zero;
        }
    };

    switch (entry.type())
    {
        case interaction::escape:
        {
            keepParticle = false;
            compat::setActive(p, false);
            U = Zero;
            count(p, pp, fate::escape, Un, ut, 0, 0, 0, 0);
            break;
        }
        case interaction::stick:
        {
            capture();
            count(p, pp, fate::capture, Un, ut, 0, 0, 0, 0);
            break;
        }
        case interaction::rebound:
        {
            // standardWallInteraction's rebound, e and mu as there
            keepParticle = true;
            compat::setActive(p, true);
            vector Uout = Urel;
            if (Un > 0)
            {
                Uout -= (1 + entry.e())*Un*nw;
            }
            Uout -= entry.mu()*Ut;
            U = Uout + Up;
            count
            (
                p, pp, fate::rebound, Un, ut, entry.e(), 0,
                max(-(Uout & nw), scalar(0)), (1 - entry.mu())*ut
            );
            break;
        }
        case interaction::adhesive:
        {
            brachDunn::Vector3 omega;
            if constexpr (isColliding<typename CloudType::parcelType>::value)
            {
                omega = toCore(p.omega());
            }

            brachDunn::Impact3D out;
            try
            {
                out = entry.model().impact
                (
                    brachDunn::Particle{p.d(), p.rho()},
                    toCore(Urel),
                    toCore(-nw),
                    omega
                );
            }
            catch (const brachDunn::InputError& err)
            {
                FatalErrorInFunction
                    << "Parcel at " << compat::position(p, this->owner().mesh())
                    << " on patch "
                    << pp.name() << ": " << err.what() << nl
                    << exit(FatalError);
            }

            const brachDunn::ImpactResult& r = out.result;
            if (r.outcome == brachDunn::Outcome::notApproaching)
            {
                keepParticle = true;
                break;
            }
            if (r.captured())
            {
                capture();
                count(p, pp, fate::capture, r.un, r.ut, r.R, r.WA, 0, 0);
                break;
            }

            keepParticle = true;
            compat::setActive(p, true);
            U = fromCore(out.U) + Up;
            if constexpr (isColliding<typename CloudType::parcelType>::value)
            {
                p.angularMomentum() =
                    p.momentOfInertia()*fromCore(out.omega);
            }
            count
            (
                p, pp, fate::rebound, r.un, r.ut, r.R, r.WA, r.unOut, r.utOut
            );
            break;
        }
        case interaction::none:
            break;
    }

    return true;
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::writeInfo(Ostream& os)
{
    const scalarField total(totalStatistics());
    const polyBoundaryMesh& bMesh = compat::boundaryMesh(this->owner().mesh());

    const auto mean = [](scalar sum, scalar n)
    {
        return n > 0 ? sum/n : scalar(0);
    };

    const label nRows = total.size()/nStatistics;
    for (label row = 0; row < nRows; ++row)
    {
        const scalar* s = &total[row*nStatistics];
        os  << "    adhesiveWallInteraction patch " << rowName(row).c_str()
            << " (parcels, particles, mass)" << nl
            << "      - impacts                     = "
            << s[reboundParcels] + s[captureParcels] + s[escapeParcels] << ", "
            << s[reboundParticles] + s[captureParticles] + s[escapeParticles]
            << ", " << s[reboundMass] + s[captureMass] + s[escapeMass] << nl
            << "      - rebounds                    = "
            << s[reboundParcels] << ", " << s[reboundParticles] << ", "
            << s[reboundMass] << nl
            << "      - captures                    = "
            << s[captureParcels] << ", " << s[captureParticles] << ", "
            << s[captureMass] << nl
            << "      - escapes                     = "
            << s[escapeParcels] << ", " << s[escapeParticles] << ", "
            << s[escapeMass] << nl
            << "      - captured: mean impact speed, angle = "
            << mean(s[captureSpeedSum], s[captureParticles]) << " m/s, "
            << mean(s[captureAngleSum], s[captureParticles]) << " deg" << nl
            << "      - rebounded: mean impact speed, angle = "
            << mean(s[reboundSpeedSum], s[reboundParticles]) << " m/s, "
            << mean(s[reboundAngleSum], s[reboundParticles]) << " deg" << nl;
    }

    if (statsFilePtr_)
    {
        OFstream& file = *statsFilePtr_;
        file << this->owner().mesh().time().value();
        for (label row = 0; row < nRows; ++row)
        {
            const scalar* s = &total[row*nStatistics];
            for (label i = 0; i < reboundSpeedSum; ++i)
            {
                file << tab << s[i];
            }
            file
                << tab << mean(s[reboundSpeedSum], s[reboundParticles])
                << tab << mean(s[reboundAngleSum], s[reboundParticles])
                << tab << mean(s[captureSpeedSum], s[captureParticles])
                << tab << mean(s[captureAngleSum], s[captureParticles]);
        }
        file << endl;
    }

    writeImpactRecords();

    if (this->writeTime())
    {
        massBalance(os, total);

        const label patchSize = nInjectors_*nStatistics;
        forAll(statPatches_, patchRow)
        {
            this->setModelProperty
            (
                bMesh[statPatches_[patchRow]].name(),
                scalarList(SubList<scalar>(total, patchSize, patchRow*patchSize))
            );
        }
        stats_ = Zero;
    }
}
