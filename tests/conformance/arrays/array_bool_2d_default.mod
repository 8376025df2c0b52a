MODULE array_bool_2d_default
  ! Tests: a 2-dimensional bool array defaults to FALSE everywhere; a single
  ! element can be set without touching its neighbours.
  VAR bool grid{3, 3};
  PROC main()
    VAR num count := 0;
    grid{2, 3} := TRUE;
    FOR r FROM 1 TO 3 DO
      FOR c FROM 1 TO 3 DO
        IF grid{r, c} count := count + 1;
      ENDFOR
    ENDFOR
    TPWrite "true cells=" \Num:=count;
    TPWrite "grid{3,2} " \Bool:=grid{3, 2};
  ENDPROC
ENDMODULE
