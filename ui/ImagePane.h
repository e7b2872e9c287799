#pragma once

#include <QImage>
#include <QWidget>

namespace vct::ui {

/**
 * Shows one image scaled to fit, keeping its aspect ratio, with a caption underneath. Small images are
 * enlarged without smoothing so single pixels stay visible when comparing renders.
 */
class ImagePane : public QWidget {
    Q_OBJECT

public:
    explicit ImagePane(const QString& caption, QWidget* parent = nullptr);

    void setImage(const QImage& image);
    const QImage& image() const { return m_image; }
    void setCaption(const QString& caption);
    QString caption() const { return m_caption; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QImage m_image;
    QString m_caption;
};

} // namespace vct::ui
