MODULE for_default_step_descending
  ! Tests: without STEP the step is 1, or -1 when FROM is greater than TO
  ! (ABB FOR description, reference 4.4): FOR i FROM 3 TO 1 visits 3, 2, 1.
  PROC main()
    FOR i FROM 3 TO 1 DO
      TPWrite "i=" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE
