MODULE DeadlockBesideFreeInput
    ! Waits for an output that nothing sets, while a free input it read
    ! earlier goes on changing.
    VAR num mode := 0;

    PROC main()
        mode := DInput(di_mode);
        WaitDO do_ready, 1;
        mode := 2;
    ENDPROC
ENDMODULE
