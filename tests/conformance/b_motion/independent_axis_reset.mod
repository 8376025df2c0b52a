MODULE IndependentAxisReset
    ! Tests: IndReset takes its reference as \RefPos (a robtarget) or \RefNum (degrees),
    ! then how the axis gets there (\Short, \Fwd, \Bwd or \Old): public code turns a
    ! turntable with 'IndReset STN1, 1 \RefNum:=0 \Short'. Resetting an independent axis
    ! changes nothing the program reads, so it runs on to its last line.
    PROC main()
        ActUnit STN1;
        IndReset STN1, 1 \RefNum:=0 \Short;
        IndReset STN1, 1 \RefNum:=90 \Fwd;
        IndReset STN1, 1 \Old;
        TPWrite "reset";
    ENDPROC
ENDMODULE
