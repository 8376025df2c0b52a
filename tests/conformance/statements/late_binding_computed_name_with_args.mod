MODULE late_binding_computed_name
  ! Tests: the late-bound name may be a computed string expression, and
  ! arguments follow the closing % as in an ordinary call.
  PROC step1(num v)
    TPWrite "step1 " \Num:=v;
  ENDPROC
  PROC step2(num v)
    TPWrite "step2 " \Num:=v * 10;
  ENDPROC
  PROC main()
    VAR string names{2} := ["1", "2"];
    FOR i FROM 1 TO 2 DO
      %"step" + names{i}% i;
    ENDFOR
  ENDPROC
ENDMODULE
