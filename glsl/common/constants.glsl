// Constants shared by the classic models' terms.
#define PI 3.14159265358979323846
