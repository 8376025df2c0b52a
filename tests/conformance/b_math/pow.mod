MODULE MainModule
  ! Tests: Pow(Base, Exponent) = Base^Exponent, argument order, integer, zero, fractional
  ! and negative exponents, negative base with integer exponent.
  PROC main()
    TPWrite "2^10=" \Num:=Pow(2, 10);
    TPWrite "10^2=" \Num:=Pow(10, 2);
    TPWrite "3^0=" \Num:=Pow(3, 0);
    TPWrite "4^0.5=" \Num:=Pow(4, 0.5);
    TPWrite "2^-2=" \Num:=Pow(2, -2);
    TPWrite "-2^3=" \Num:=Pow(-2, 3);
  ENDPROC
ENDMODULE
