MODULE if_elseif_else
  ! Tests: IF/ELSEIF/ELSE runs exactly the first branch whose condition is
  ! TRUE, or the ELSE branch when none is.
  PROC classify(num v)
    IF v < 3 THEN
      TPWrite "small " \Num:=v;
    ELSEIF v < 8 THEN
      TPWrite "medium " \Num:=v;
    ELSEIF v < 6 THEN
      TPWrite "never " \Num:=v;
    ELSE
      TPWrite "large " \Num:=v;
    ENDIF
  ENDPROC
  PROC main()
    classify 1;
    classify 5;
    classify 10;
  ENDPROC
ENDMODULE
