MODULE StubReraise
    ! The failing line is a bare RAISE that passes on an error: the headline names the
    ! statement that raised it and the stub function whose neutral value caused it.
    VAR num ratio := 0;

    PROC main()
        Pick;
    ENDPROC

    PROC Pick()
        ratio := 100 / GripForce();
    ERROR
        RAISE;
    ENDPROC
ENDMODULE
