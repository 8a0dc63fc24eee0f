// Virtual shadow maps: the clearing triangle writes depth only.
void main() {}
