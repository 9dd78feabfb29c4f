#include "tracker/unzueta/point_kalman.h"

namespace simcap::tracker {

PointKalman::PointKalman(cv::Point2d position, const PointKalmanNoise& noise,
                         double initial_velocity_variance, cv::Point2d velocity)
    : filter_(4, 2, 0, CV_64F) {
  filter_.transitionMatrix = (cv::Mat_<double>(4, 4) << 1, 0, 1, 0,  //
                              0, 1, 0, 1,                            //
                              0, 0, 1, 0,                            //
                              0, 0, 0, 1);
  filter_.measurementMatrix = (cv::Mat_<double>(2, 4) << 1, 0, 0, 0, 0, 1, 0, 0);
  cv::setIdentity(filter_.processNoiseCov, cv::Scalar::all(noise.process));
  cv::setIdentity(filter_.measurementNoiseCov, cv::Scalar::all(noise.measurement));
  filter_.statePost = (cv::Mat_<double>(4, 1) << position.x, position.y, velocity.x, velocity.y);
  filter_.errorCovPost =
      cv::Mat::diag((cv::Mat_<double>(4, 1) << noise.measurement, noise.measurement,
                     initial_velocity_variance, initial_velocity_variance));
  filter_.statePre = filter_.statePost.clone();
  filter_.errorCovPre = filter_.errorCovPost.clone();
}

cv::Point2d PointKalman::predict() {
  const cv::Mat& x = filter_.predict();
  return {x.at<double>(0), x.at<double>(1)};
}

double PointKalman::mahalanobis2(cv::Point2d measured) const {
  const cv::Mat& H = filter_.measurementMatrix;
  const cv::Mat S = H * filter_.errorCovPre * H.t() + filter_.measurementNoiseCov;
  const cv::Mat y = (cv::Mat_<double>(2, 1) << measured.x - filter_.statePre.at<double>(0),
                     measured.y - filter_.statePre.at<double>(1));
  return cv::Mat(y.t() * S.inv(cv::DECOMP_CHOLESKY) * y).at<double>(0);
}

cv::Point2d PointKalman::correct(cv::Point2d measured) {
  const cv::Mat& x = filter_.correct((cv::Mat_<double>(2, 1) << measured.x, measured.y));
  return {x.at<double>(0), x.at<double>(1)};
}

void PointKalman::coast() {
  filter_.statePre.copyTo(filter_.statePost);
  filter_.errorCovPre.copyTo(filter_.errorCovPost);
}

void PointKalman::translate(cv::Point2d delta) {
  filter_.statePost.at<double>(0) += delta.x;
  filter_.statePost.at<double>(1) += delta.y;
}

cv::Point2d PointKalman::position() const {
  return {filter_.statePost.at<double>(0), filter_.statePost.at<double>(1)};
}

cv::Point2d PointKalman::velocity() const {
  return {filter_.statePost.at<double>(2), filter_.statePost.at<double>(3)};
}

}  // namespace simcap::tracker
