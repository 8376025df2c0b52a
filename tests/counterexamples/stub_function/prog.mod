MODULE StubFunction
    ! The failing line divides by what a stub function returns: the headline names the stub.
    VAR num ratio := 0;

    PROC main()
        ratio := 100 / ReadScale();
    ENDPROC
ENDMODULE
