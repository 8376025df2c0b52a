MODULE KeptInputOrigin
    ! A property reads diStart, so the state keeps it and each step chooses it anew: the
    ! headline's doCycle was set by SetDO, not from that input.
    PROC main()
        WaitDI diStart, 1;
        SetDO doCycle, 1;
        WaitDO doCycle, 0;
    ENDPROC
ENDMODULE
