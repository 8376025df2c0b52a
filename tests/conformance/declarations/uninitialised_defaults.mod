MODULE uninitialised_defaults
  ! Tests: VAR data without initialiser: num 0, dnum 0, bool FALSE, string
  ! "" (module and routine data alike).
  VAR num mn;
  VAR bool mb;
  PROC main()
    VAR num n;
    VAR dnum d;
    VAR bool b;
    VAR string s;
    TPWrite "mn=" \Num:=mn;
    TPWrite "mb=" \Bool:=mb;
    TPWrite "n=" \Num:=n;
    TPWrite "d=" \Dnum:=d;
    TPWrite "b=" \Bool:=b;
    TPWrite "s=[" + s + "]";
  ENDPROC
ENDMODULE
