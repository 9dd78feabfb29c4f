#include "tracker/unzueta/gesture_classifier.h"

#include <algorithm>

#include "core/error.h"

namespace simcap::tracker {

namespace {

cv::Mat row_of(const Eigen::VectorXd& v) {
  cv::Mat m(1, static_cast<int>(v.size()), CV_32F);
  for (Eigen::Index i = 0; i < v.size(); ++i)
    m.at<float>(0, static_cast<int>(i)) = static_cast<float>(v[i]);
  return m;
}

}  // namespace

void GestureClassifier::train(const std::vector<Eigen::VectorXd>& samples,
                              const std::vector<std::string>& labels) {
  if (samples.empty() || samples.size() != labels.size()) {
    throw Error("gesture classifier: expected as many labels as samples, and at least one");
  }
  names_ = labels;
  std::sort(names_.begin(), names_.end());
  names_.erase(std::unique(names_.begin(), names_.end()), names_.end());
  cv::Mat x(static_cast<int>(samples.size()), static_cast<int>(samples[0].size()), CV_32F);
  cv::Mat y(static_cast<int>(samples.size()), 1, CV_32S);
  for (size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].size() != samples[0].size()) {
      throw Error("gesture classifier: samples of different lengths");
    }
    row_of(samples[i]).copyTo(x.row(static_cast<int>(i)));
    y.at<int>(static_cast<int>(i)) = static_cast<int>(
        std::lower_bound(names_.begin(), names_.end(), labels[i]) - names_.begin());
  }
  if (kind_ == GestureClassifierKind::knn) {
    auto knn = cv::ml::KNearest::create();
    knn->setDefaultK(k_);
    knn->setIsClassifier(true);
    knn->setAlgorithmType(cv::ml::KNearest::BRUTE_FORCE);
    knn->train(x, cv::ml::ROW_SAMPLE, y);
    model_ = knn;
    return;
  }
  if (names_.size() < 2) throw Error("gesture classifier: the SVM needs at least two labels");
  auto svm = cv::ml::SVM::create();
  svm->setType(cv::ml::SVM::C_SVC);
  svm->setKernel(cv::ml::SVM::POLY);
  svm->setDegree(3);
  svm->setGamma(0.01);
  svm->setCoef0(0);
  svm->setC(10);
  svm->setTermCriteria({cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, 10000, 1e-6});
  svm->train(x, cv::ml::ROW_SAMPLE, y);
  model_ = svm;
}

std::string GestureClassifier::predict(const Eigen::VectorXd& sample) const {
  if (!model_) throw Error("gesture classifier: predict before train");
  const cv::Mat x = row_of(sample);
  float label = 0;
  if (kind_ == GestureClassifierKind::knn) {
    cv::Mat result;
    label = static_cast<cv::ml::KNearest&>(*model_).findNearest(x, k_, result);
  } else {
    label = model_->predict(x);
  }
  const int i = static_cast<int>(label);
  if (i < 0 || i >= static_cast<int>(names_.size())) throw Error("gesture classifier: bad label");
  return names_[static_cast<size_t>(i)];
}

}  // namespace simcap::tracker
