MODULE alternative_parameters
  ! Tests: mutually exclusive optional parameters \num Mm | num Inch: the
  ! caller gives at most one of them and the routine sees which with Present.
  PROC show(\num Mm | num Inch)
    IF Present(Mm) THEN
      TPWrite "mm " \Num:=Mm;
    ELSEIF Present(Inch) THEN
      TPWrite "mm " \Num:=Inch * 25;
    ELSE
      TPWrite "none";
    ENDIF
  ENDPROC
  PROC main()
    show \Mm:=30;
    show \Inch:=2;
    show;
  ENDPROC
ENDMODULE
