MODULE SameValueOrigin
    ! divisor is assigned 0 again at line 9: its value comes from that assignment, not from
    ! its initial value, although the assignment changed nothing.
    VAR num divisor := 0;
    VAR num ratio := 0;

    PROC main()
        ratio := 1;
        divisor := 0;
        ratio := 100 / divisor;
    ENDPROC
ENDMODULE
