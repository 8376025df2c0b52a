MODULE argument_evaluation_by_value
  ! Tests: an IN argument is evaluated once at the call: later changes to the
  ! caller's variable through a VAR parameter do not change the IN copy.
  PROC mix(VAR num target, num snapshot)
    target := 100;
    TPWrite "snapshot=" \Num:=snapshot;
    TPWrite "target=" \Num:=target;
  ENDPROC
  PROC main()
    VAR num x := 1;
    mix x, x;
  ENDPROC
ENDMODULE
