#line -1
void main()
{
}
