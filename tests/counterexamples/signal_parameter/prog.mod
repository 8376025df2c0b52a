MODULE SignalParameter
    ! A helper routine waits on the signal it is passed: the deadlock's last step names the
    ! signal the parameter holds (doClamp), not only its type.
    VAR num cycles := 0;

    PROC main()
        SetDO doLamp, 1;
        WaitHigh doLamp;
        cycles := cycles + 1;
        WaitHigh doClamp;
    ENDPROC

    PROC WaitHigh(VAR signaldo s)
        WaitDO s, 1;
    ENDPROC
ENDMODULE
