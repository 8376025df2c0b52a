MODULE CfgUnknownInstance
    ! A seventh arm is not part of a standard robot, and nothing says it is absent:
    ! both outcomes stay, so the unhandled ERR_CFG_NOTFND is still found. An attribute
    ! a standard arm is not known to have is not known either.
    VAR num bound := 0;
    VAR num mode := 0;

    PROC main()
        ReadCfgData "/MOC/ARM/rob1_2", "no_such_attribute", mode;
        ReadCfgData "/MOC/ARM/rob1_7", "upper_joint_bound", bound;
    ENDPROC
ENDMODULE
