MODULE StubValue
    ! The tool's weight comes from a module this program does not have: the stubs give it
    ! a neutral value (0), and the division by it fails.
    VAR num ratio := 0;

    PROC main()
        ratio := 100 / gripper_mass;
    ENDPROC
ENDMODULE
