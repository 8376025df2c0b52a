MODULE for_basic
  ! Tests: FOR counts from FROM to TO inclusive with step 1.
  PROC main()
    FOR i FROM 1 TO 3 DO
      TPWrite "i=" \Num:=i;
    ENDFOR
    TPWrite "done";
  ENDPROC
ENDMODULE
