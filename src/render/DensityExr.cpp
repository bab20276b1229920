// The OpenEXR half of render/DensityFile.h: the only file that includes OpenEXR's headers
// (compile time: they stay out of every other translation unit).

#include "render/DensityFile.h"

#include <QCoreApplication>
#include <QFile>
#include <QIODevice>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <cstring>
#include <exception>

namespace awb {

namespace {

struct ExrTr {
    Q_DECLARE_TR_FUNCTIONS(awb::DensityFile)
};

constexpr const char *kWorldMin = "attractorWorkbenchWorldMin";
constexpr const char *kWorldMax = "attractorWorkbenchWorldMax";

// OpenEXR's output stream over a Qt device (the figure writer's buffer).
class DeviceStream : public Imf::OStream {
public:
    explicit DeviceStream(QIODevice &device) : Imf::OStream("density.exr"), m_device(device) {}
    void write(const char c[], int n) override
    {
        if (m_device.write(c, n) != n)
            throw std::runtime_error(m_device.errorString().toStdString());
    }
    uint64_t tellp() override { return uint64_t(m_device.pos()); }
    void seekp(uint64_t pos) override
    {
        if (!m_device.seek(qint64(pos)))
            throw std::runtime_error("cannot seek");
    }

private:
    QIODevice &m_device;
};

const char *kChannels[4] = {"R", "G", "B", "A"};

} // namespace

bool writeDensityExr(const QString &fileName, const AttractorDensity &d,
                     const DensityFileInfo &info, QString *error)
{
    const int W = d.frame.width, H = d.frame.height;
    if (d.rgba.size() != 4 * std::size_t(W) * std::size_t(H)) {
        if (error)
            *error = ExrTr::tr("cannot write %1: the picture is empty").arg(fileName);
        return false;
    }
    return writeFigureFile(
        fileName,
        [&](QIODevice &out, QString *why) {
            try {
                Imf::Header header(W, H);
                for (const char *c : kChannels)
                    header.channels().insert(c, Imf::Channel(Imf::FLOAT));
                header.insert("comments", Imf::StringAttribute(info.what.toStdString()));
                header.insert("software", Imf::StringAttribute(
                                              ("Attractor Workbench "
                                               + QCoreApplication::applicationVersion())
                                                  .toStdString()));
                header.insert(kWorldMin,
                              Imf::V2dAttribute(Imath::V2d(info.world.left(), info.world.top())));
                header.insert(kWorldMax, Imf::V2dAttribute(Imath::V2d(info.world.right(),
                                                                      info.world.bottom())));
                for (const auto &[key, text] : info.metadata.pngText)
                    if (key == QLatin1String("attractor-workbench:project"))
                        header.insert("attractorWorkbenchProject",
                                      Imf::StringAttribute(text.toStdString()));
                DeviceStream stream(out);
                Imf::OutputFile file(stream, header);
                Imf::FrameBuffer buffer;
                const std::size_t xs = 4 * sizeof(float), ys = xs * std::size_t(W);
                auto *base = const_cast<char *>(reinterpret_cast<const char *>(d.rgba.data()));
                for (int k = 0; k < 4; ++k)
                    buffer.insert(kChannels[k],
                                  Imf::Slice(Imf::FLOAT, base + k * sizeof(float), xs, ys));
                file.setFrameBuffer(buffer);
                file.writePixels(H);
                return true;
            } catch (const std::exception &e) {
                if (why)
                    *why = QString::fromUtf8(e.what());
                return false;
            }
        },
        error);
}

AttractorDensity readDensityExr(const QString &fileName, QRectF *world, QString *error)
{
    AttractorDensity out;
    try {
        Imf::InputFile file(QFile::encodeName(fileName).constData());
        const Imath::Box2i dw = file.header().dataWindow();
        const int W = dw.max.x - dw.min.x + 1, H = dw.max.y - dw.min.y + 1;
        out.frame.width = W;
        out.frame.height = H;
        out.rgba.assign(4 * std::size_t(W) * std::size_t(H), 0.0f);
        Imf::FrameBuffer buffer;
        const std::size_t xs = 4 * sizeof(float), ys = xs * std::size_t(W);
        char *base = reinterpret_cast<char *>(out.rgba.data())
                     - (std::ptrdiff_t(dw.min.x) * xs + std::ptrdiff_t(dw.min.y) * ys);
        for (int k = 0; k < 4; ++k)
            buffer.insert(kChannels[k], Imf::Slice(Imf::FLOAT, base + k * sizeof(float), xs, ys));
        file.setFrameBuffer(buffer);
        file.readPixels(dw.min.y, dw.max.y);
        const auto *lo = file.header().findTypedAttribute<Imf::V2dAttribute>(kWorldMin);
        const auto *hi = file.header().findTypedAttribute<Imf::V2dAttribute>(kWorldMax);
        if (world && lo && hi) {
            *world = QRectF(QPointF(lo->value().x, lo->value().y),
                            QPointF(hi->value().x, hi->value().y));
            out.frame.x0 = lo->value().x, out.frame.y0 = lo->value().y;
            out.frame.x1 = hi->value().x, out.frame.y1 = hi->value().y;
        }
    } catch (const std::exception &e) {
        if (error)
            *error = ExrTr::tr("cannot read %1: %2").arg(fileName, QString::fromUtf8(e.what()));
        return {};
    }
    return out;
}

} // namespace awb
