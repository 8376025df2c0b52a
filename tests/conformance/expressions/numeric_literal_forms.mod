MODULE numeric_literal_forms
  ! Tests: numeric literal forms: hexadecimal 0x, octal 0o, binary 0b,
  ! exponent, leading and trailing decimal point.
  PROC main()
    TPWrite "0xFF=" \Num:=0xFF;
    TPWrite "0o17=" \Num:=0o17;
    TPWrite "0b101=" \Num:=0b101;
    TPWrite "1.5E2=" \Num:=1.5E2;
    TPWrite ".5=" \Num:=.5;
    TPWrite "3.=" \Num:=3.;
    TPWrite "25e-1=" \Num:=25e-1;
  ENDPROC
ENDMODULE
